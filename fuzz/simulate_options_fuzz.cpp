// `epviz simulate`'s simulation options, as the shell hands them over (the
// input is argv, NUL-separated), through CLI11 and the same option table and
// conversions as the command, to a checked simulation. Bad input must end in
// the error a user sees (exit 2), never in a crash.
#include <CLI/CLI.hpp>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "app/cli.hpp"
#include "app/simulation_fields.hpp"
#include "io/bad_input.hpp"
#include "job/resolve.hpp"

namespace {

using namespace epviz;

void parse_simulate(const std::vector<std::string>& args) {
  CLI::App app{"fuzz"};
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);  // as main()
  app::SimulationOptions options;
  app::add_simulation_options(app, options);
  app::cli::reject_empty_values(app);
  std::vector<const char*> argv{"epviz-simulate"};
  for (const auto& a : args) argv.push_back(a.c_str());
  app.parse(int(argv.size()), argv.data());
  (void)job::resolve(app::fields_from_options(options));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> args(1);
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == 0)
      args.emplace_back();
    else
      args.back() += char(data[i]);
  }
  try {
    parse_simulate(args);
  } catch (const CLI::Error&) {
  } catch (const io::BadInput&) {
  }
  return 0;
}
