#pragma once
// Values typed on the command line, read strictly: a number, an integer in a
// range, a vector X,Y,Z. Anything else is io::BadInput naming the option and
// quoting the value on one line (printable.hpp).
#include <array>
#include <string>

namespace epviz::io {

// A finite number, all of `text` read ("1e-3", not "1e-3x", "nan" or "").
double parse_number(const std::string& option, const std::string& text);
// An integer from `min_value` to `max_value`.
long parse_integer(const std::string& option, const std::string& text, long min_value,
                   long max_value);
// "1,2.5,3e-1" -> {1, 2.5, 0.3}: exactly three finite numbers.
std::array<double, 3> parse_vec3(const std::string& option, const std::string& text);

}  // namespace epviz::io
