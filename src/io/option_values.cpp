#include "io/option_values.hpp"

#include <charconv>
#include <cmath>

#include "io/bad_input.hpp"
#include "io/printable.hpp"

namespace epviz::io {
namespace {

bool to_double(const std::string& s, double& out) {
  if (s.empty()) return false;
  const char* end = s.data() + s.size();
  auto [ptr, ec] = std::from_chars(s.data(), end, out);
  return ec == std::errc() && ptr == end && std::isfinite(out);
}

}  // namespace

double parse_number(const std::string& option, const std::string& text) {
  double x = 0.0;
  if (!to_double(text, x))
    throw BadInput(option + ": expected a finite number, got '" + printable(text) + "'");
  return x;
}

long parse_integer(const std::string& option, const std::string& text, long min_value,
                   long max_value) {
  long x = 0;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, x);
  if (text.empty() || ec != std::errc() || ptr != end || x < min_value || x > max_value)
    throw BadInput(option + ": expected an integer from " + std::to_string(min_value) + " to " +
                   std::to_string(max_value) + ", got '" + printable(text) + "'");
  return x;
}

std::array<double, 3> parse_vec3(const std::string& option, const std::string& text) {
  std::array<double, 3> v{};
  std::size_t start = 0;
  for (int i = 0; i < 3; ++i) {
    const std::size_t comma = text.find(',', start);
    const bool last = (i == 2);
    if (last != (comma == std::string::npos) ||
        !to_double(text.substr(start, last ? std::string::npos : comma - start), v[i]))
      throw BadInput(option + ": expected three comma-separated finite numbers X,Y,Z, got '" +
                     printable(text) + "'");
    start = comma + 1;
  }
  return v;
}

}  // namespace epviz::io
