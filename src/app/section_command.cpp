#include "app/section_command.hpp"

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <memory>
#include <thread>

#include "app/cli_values.hpp"
#include "io/output_paths.hpp"
#include "section/section_csv.hpp"
#include "section/section_job.hpp"
#include "section/section_run.hpp"

namespace epviz::app {
namespace {

struct SectionOptions {
  std::string file, jobs;
};

int run_section(const SectionOptions& o) {
  const section::SectionJob job = section::read_section_job(o.file);
  const int threads = o.jobs.empty() ? int(std::max(1u, std::thread::hardware_concurrency()))
                                     : int(parse_integer("-j", o.jobs, 1, 4096));
  io::check_output_file(o.file + ": key 'csv'", job.csv);
  const auto starts = section::section_starts(job);

  const auto start = std::chrono::steady_clock::now();
  const auto results = section::run_section(job, starts, threads);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (const std::string lost = section::lost_orbits_line(results); !lost.empty()) {
    std::fprintf(stderr, "epviz: error: %s: %s (nothing written)\n", o.file.c_str(), lost.c_str());
    return 3;
  }
  section::write_crossings_csv(job, results);
  long crossings = 0;
  for (const auto& r : results) crossings += long(r.crossings.size());
  std::fprintf(job.csv == "-" ? stderr : stdout,
               "%s: %zu orbits, %ld crossings in %.2f s (%d threads) -> %s\n", o.file.c_str(),
               results.size(), crossings, seconds, threads, job.csv.c_str());
  return 0;
}

}  // namespace

std::function<int()> add_section_command(CLI::App& app) {
  auto o = std::make_shared<SectionOptions>();
  auto* cmd = app.add_subcommand(
      "section", "Poincare section (SECTION.json): crossings of a surface by orbits on a level");
  cmd->add_option("section", o->file, "section file (JSON; docs/sections.md)")->required();
  cmd->add_option("-j,--jobs", o->jobs, "threads (default: all cores)");
  return [o] { return run_section(*o); };
}

}  // namespace epviz::app
