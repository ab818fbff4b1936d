// The only file that includes CLI11 (app/cli.hpp says why).
#include "app/cli.hpp"

#include <CLI/CLI.hpp>
#include <cstdio>

namespace epviz::app::cli {

Option Option::required() {
  option_->required();
  return *this;
}

Option Option::take_all() {
  option_->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  return *this;
}

Option Option::show_default() {
  option_->capture_default_str();
  return *this;
}

Option Option::one_value_per_use() {
  option_->allow_extra_args(false);
  return *this;
}

Command Command::add_subcommand(const std::string& name, const std::string& description) {
  return Command(*app_->add_subcommand(name, description));
}

Option Command::add_option(const std::string& name, std::string& value,
                           const std::string& description) {
  return Option(app_->add_option(name, value, description));
}

Option Command::add_option(const std::string& name, std::vector<std::string>& values,
                           const std::string& description) {
  return Option(app_->add_option(name, values, description));
}

Option Command::add_flag(const std::string& name, bool& value, const std::string& description) {
  return Option(app_->add_flag(name, value, description));
}

namespace {

void reject_empty(CLI::App& command) {
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
  for (CLI::App* sub : command.get_subcommands({})) reject_empty(*sub);
}

}  // namespace

void reject_empty_values(Command command) { reject_empty(*command.app_); }

Program::Program(const std::string& description) : app_(std::make_unique<CLI::App>(description)) {
  app_->require_subcommand(1);
  app_->option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
}

Program::~Program() = default;

Command Program::root() { return Command(*app_); }

void Program::set_version_flag(const std::string& flag, std::function<std::string()> text) {
  app_->set_version_flag(flag, std::move(text));
}

void Program::fallthrough() { app_->fallthrough(); }

std::optional<int> Program::parse(int argc, char** argv) {
  try {
    app_->parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app_->exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app_->exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app_->exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "epviz: error: %s (see epviz --help)\n", e.what());
    return 2;
  }
  return std::nullopt;
}

std::string Program::subcommand() const {
  for (const CLI::App* sub : app_->get_subcommands()) return sub->get_name();
  return "";
}

}  // namespace epviz::app::cli
