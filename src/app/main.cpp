// The epviz command line. Every user error ends here as one line on stderr and
// exit code 2; numerical failures are reported by the commands (exit code 3).
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <string>

#include "app/bench_command.hpp"
#include "app/cases_command.hpp"
#include "app/cli.hpp"
#include "app/diagram_command.hpp"
#include "app/merge_command.hpp"
#include "app/section_command.hpp"
#include "app/simulate_command.hpp"
#include "app/sweep_command.hpp"
#ifdef EPVIZ_HAVE_RENDER
#include "app/check_command.hpp"
#include "app/render_command.hpp"
#include "app/serve_command.hpp"
#include "render/gl_context.hpp"
#endif
#include "io/bad_input.hpp"
#include "io/printable.hpp"
#include "numerics/simd_path.hpp"

int main(int argc, char** argv) {
  epviz::app::cli::Program program{
      "epviz: the heavy rigid body about a fixed point (Euler-Poisson), simulated and rendered "
      "offscreen"};
  // One subcommand; an option given twice takes its last value, so a command
  // line can override what a wrapper script put before it (app/cli.hpp).
  program.set_version_flag("--version", [] {
    std::string text = "epviz " EPVIZ_VERSION " (git " EPVIZ_GIT_COMMIT ")";
    text += "\nbatch SIMD path: " + epviz::numerics::simd_path_report();
#ifdef EPVIZ_HAVE_RENDER
    text += "\nGL backend (auto): " + epviz::render::probe_gl_backend();
#endif
    return text;
  });
  epviz::app::cli::Command app = program.root();
#ifdef EPVIZ_HAVE_RENDER
  bool verbose = false;
  app.add_flag("--verbose", verbose, "say on stderr which GL backend was chosen");
  program.fallthrough();  // --verbose may also follow the command
#endif
  std::map<std::string, std::function<int()>> commands;
  commands["simulate"] = epviz::app::add_simulate_command(app);
  commands["cases"] = epviz::app::add_cases_command(app);
  commands["bench"] = epviz::app::add_bench_command(app);
  commands["sweep"] = epviz::app::add_sweep_command(app);
  commands["merge"] = epviz::app::add_merge_command(app);
  commands["section"] = epviz::app::add_section_command(app);
  commands["diagram"] = epviz::app::add_diagram_command(app);
#ifdef EPVIZ_HAVE_RENDER
  commands["render"] = epviz::app::add_render_command(app);
  commands["check"] = epviz::app::add_check_command(app);
  commands["serve"] = epviz::app::add_serve_command(app);
#endif
  epviz::app::cli::reject_empty_values(app);

  if (const auto exit_code = program.parse(argc, argv)) return *exit_code;
#ifdef EPVIZ_HAVE_RENDER
  epviz::render::set_gl_verbose(verbose);
#endif
  try {
    // EPVIZ_SIMD is input to every command that integrates in batches
    // (sweep, section, render's clouds): checked before any of them starts.
    try {
      (void)epviz::numerics::chosen_simd_path();
    } catch (const std::invalid_argument& e) {
      // "EPVIZ_SIMD=VALUE: why", with the value quoted as every message quotes one.
      const char* set = std::getenv("EPVIZ_SIMD");
      const std::string given = "EPVIZ_SIMD=" + std::string(set ? set : ""), why = e.what();
      if (!why.starts_with(given)) throw epviz::io::BadInput(epviz::io::printable(why, 300));
      throw epviz::io::BadInput("EPVIZ_SIMD=" + epviz::io::quoted(set) + why.substr(given.size()));
    }
    if (const std::string name = program.subcommand(); !name.empty()) return commands.at(name)();
  } catch (const epviz::io::BadInput& e) {
    std::fprintf(stderr, "epviz: error: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "epviz: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
