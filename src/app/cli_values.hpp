#pragma once
// Parsing of command-line values, with messages that name the option.
#include <array>
#include <string>

namespace epviz::app {

// "1,2.5,3e-1" -> {1, 2.5, 0.3}; throws UsageError naming `option` otherwise.
std::array<double, 3> parse_vec3(const std::string& option, const std::string& text);
double parse_number(const std::string& option, const std::string& text);
long parse_integer(const std::string& option, const std::string& text, long min_value,
                   long max_value);

}  // namespace epviz::app
