#include "app/cli_values.hpp"

#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>
#include <filesystem>

#include "io/bad_input.hpp"
#include "io/printable.hpp"

namespace epviz::app {
namespace {

bool to_double(const std::string& s, double& out) {
  if (s.empty()) return false;
  const char* end = s.data() + s.size();
  auto [ptr, ec] = std::from_chars(s.data(), end, out);
  return ec == std::errc() && ptr == end && std::isfinite(out);
}

// The file a path names, so that two spellings of it compare equal.
std::filesystem::path canonical_file(const std::string& path) {
  std::error_code ec;
  auto p = std::filesystem::weakly_canonical(std::filesystem::absolute(path, ec), ec);
  return ec ? std::filesystem::absolute(path).lexically_normal() : p;
}

}  // namespace

double parse_number(const std::string& option, const std::string& text) {
  double x = 0.0;
  if (!to_double(text, x))
    throw io::BadInput(option + ": expected a finite number, got '" + io::printable(text) + "'");
  return x;
}

long parse_integer(const std::string& option, const std::string& text, long min_value,
                   long max_value) {
  long x = 0;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, x);
  if (text.empty() || ec != std::errc() || ptr != end || x < min_value || x > max_value)
    throw io::BadInput(option + ": expected an integer from " + std::to_string(min_value) + " to " +
                       std::to_string(max_value) + ", got '" + io::printable(text) + "'");
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
      throw io::BadInput(option + ": expected three comma-separated finite numbers X,Y,Z, got '" +
                         io::printable(text) + "'");
    start = comma + 1;
  }
  return v;
}

void reject_empty_values(CLI::App& command) {
  const CLI::Validator non_empty(
      [](std::string& value) {
        return value.empty() ? std::string(
                                   "an empty value is not allowed; leave the option out "
                                   "for its default")
                             : std::string();
      },
      "", "non-empty");  // no description: the help stays as it was
  for (CLI::Option* option : command.get_options())
    if (option->get_type_size_max() > 0) option->check(non_empty);
  for (CLI::App* sub : command.get_subcommands({})) reject_empty_values(*sub);
}

void require_distinct_files(const std::vector<std::pair<std::string, std::string>>& outputs) {
  for (std::size_t i = 0; i < outputs.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) {
      const auto& [a_option, a] = outputs[j];
      const auto& [b_option, b] = outputs[i];
      if (a.empty() || b.empty() || a == "-" || b == "-") continue;
      if (canonical_file(a) == canonical_file(b))
        throw io::BadInput(b_option + ": the same file as " + a_option + " ('" + io::printable(b) +
                           "'); give each its own file");
    }
}

}  // namespace epviz::app
