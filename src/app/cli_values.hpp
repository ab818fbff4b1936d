#pragma once
// Parsing of command-line values, with messages that name the option and
// quote the value on one line (io::printable).
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace CLI {
class App;  // CLI11: included only where options are defined
}

namespace epviz::app {

// "1,2.5,3e-1" -> {1, 2.5, 0.3}; throws io::BadInput naming `option` otherwise.
std::array<double, 3> parse_vec3(const std::string& option, const std::string& text);
double parse_number(const std::string& option, const std::string& text);
long parse_integer(const std::string& option, const std::string& text, long min_value,
                   long max_value);

// Makes an empty value (`--case ''`) an error of every option of `command`
// and of its subcommands that takes a value, instead of the same as not giving
// the option. Call it once every option is added.
void reject_empty_values(CLI::App& command);

// Throws io::BadInput if two of the (option, path) pairs name the same file,
// however spelled ("out.csv", "./out.csv", a symlink to it); empty paths and
// "-" (standard output) are skipped.
void require_distinct_files(const std::vector<std::pair<std::string, std::string>>& outputs);

}  // namespace epviz::app
