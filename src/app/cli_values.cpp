#include "app/cli_values.hpp"

#include <CLI/CLI.hpp>

namespace epviz::app {

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

}  // namespace epviz::app
