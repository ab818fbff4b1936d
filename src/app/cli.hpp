#pragma once
// The command line's own face of CLI11: the commands add their options through
// these few calls, and only app/cli.cpp includes <CLI/CLI.hpp>. CLI11 (2.1 on
// Debian 12) is header-only, and every file that includes it compiles its
// validators and option templates again at about 6 s of CPU each; behind this
// header it is compiled once (docs/benchmarks.md, "Build and test time").
// Each call is the CLI11 call of the same name, so help and errors read as
// CLI11 writes them.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace epviz::app::cli {

// An option once added; its settings chain (`.required().take_all()`).
class Option {
 public:
  explicit Option(CLI::Option* option) : option_(option) {}
  // The option (a positional argument) must be given.
  Option required();
  // Every value given is kept (CLI11's MultiOptionPolicy::TakeAll), not the last.
  Option take_all();
  // The help shows the variable's value when the option is added as its default.
  Option show_default();
  // A repeatable option takes one value per use (`--x A --x B`, not `--x A B`).
  Option one_value_per_use();

 private:
  CLI::Option* option_;
};

// A command, the program's or a subcommand, to add options to.
class Command {
 public:
  // Implicit: the fuzz target wraps its own CLI::App.
  Command(CLI::App& app) : app_(&app) {}  // NOLINT(google-explicit-constructor)

  Command add_subcommand(const std::string& name, const std::string& description);
  // `name` as CLI11 takes it: "--out", "-j,--jobs", or a positional "job".
  Option add_option(const std::string& name, std::string& value, const std::string& description);
  Option add_option(const std::string& name, std::vector<std::string>& values,
                    const std::string& description);
  Option add_flag(const std::string& name, bool& value, const std::string& description);

 private:
  friend void reject_empty_values(Command command);
  CLI::App* app_;
};

// Makes an empty value (`--case ''`) an error of every option of `command`
// and of its subcommands that takes a value, instead of the same as not giving
// the option. Call it once every option is added.
void reject_empty_values(Command command);

// The program's command line: one subcommand required, and an option given
// twice takes its last value (so that a command line can override what a
// wrapper script put before it).
class Program {
 public:
  explicit Program(const std::string& description);
  ~Program();
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;

  Command root();
  // `flag` prints what `text` returns and ends the program (exit 0).
  void set_version_flag(const std::string& flag, std::function<std::string()> text);
  // The program's own options may also follow the subcommand.
  void fallthrough();
  // Parses the command line. nullopt: a subcommand is to run; else the exit
  // code, after the help or the version was printed or the error said on
  // stderr ("epviz: error: ... (see epviz --help)", exit 2).
  std::optional<int> parse(int argc, char** argv);
  // The subcommand given ("" before parse()).
  std::string subcommand() const;

 private:
  std::unique_ptr<CLI::App> app_;
};

}  // namespace epviz::app::cli
