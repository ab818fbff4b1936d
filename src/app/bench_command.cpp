#include "app/bench_command.hpp"

#include <CLI/CLI.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/gl_option.hpp"
#include "io/atomic_file.hpp"
#include "io/bad_input.hpp"
#include "io/output_paths.hpp"
#include "job/job_file.hpp"
#include "job/resolve.hpp"
#include "study/bench_json.hpp"
#include "study/bench_studies.hpp"
#include "study/bench_tables.hpp"
#ifdef EPVIZ_HAVE_RENDER
#include "render/gl_choice.hpp"
#include "study/bench_figures.hpp"
#include "vector/figure_files.hpp"
#endif

namespace epviz::app {
namespace {

namespace fs = std::filesystem;

// The body and initial state of a render job's "simulation" (a single job),
// checked as `epviz render` checks them.
study::Problem job_problem(const std::string& file) {
  if (!fs::is_regular_file(file)) throw io::BadInput("--job: no such file '" + file + "'");
  const job::LoadedJob loaded = job::load_job_file(file);
  if (!loaded.single)
    throw io::BadInput("--job: '" + file +
                       "' is a gallery or bench-figures job; expected a single render job");
  return study::run_problem(job::resolve(loaded.single->simulation));
}

void write_outputs(const BenchRequest& request, const std::vector<study::StudyRow>& rows,
                   double wall) {
  if (request.json.empty() && request.out.empty()) return;
  const std::string text = study::bench_document(rows, request.quick, wall).dump(1) + "\n";
  if (!request.json.empty()) io::write_file_atomically(request.json, text);
  if (request.out.empty()) return;
  io::write_file_atomically(fs::path(request.out) / "bench.json", text);
#ifdef EPVIZ_HAVE_RENDER
  const auto written =
      vector::write_figures(study::bench_figures(rows), request.out,
                            vector::parse_figure_format(request.format), request.gl);
  std::printf("%zu charts written to %s\n", written.size(), request.out.c_str());
#endif
}

}  // namespace

int run_bench(const BenchRequest& request) {
  // Every option is checked before the studies, which take minutes.
  study::StudyOptions opts;
  opts.quick = request.quick;
  if (!request.job.empty()) opts.custom = job_problem(request.job);
  opts.cases = study::parse_case_list(request.cases, !request.job.empty());
#ifdef EPVIZ_HAVE_RENDER
  (void)vector::parse_figure_format(request.format);
  (void)render::GlChoice(request.gl);
#endif
  io::check_output_file("--json", request.json);
  if (!request.out.empty()) {
    io::check_output_dir("--out", request.out);
    io::make_output_folder("--out", request.out);
  }

  bool first = true;  // the first line says whether the run is quick
  const auto note = [&](const std::string& line) {
    std::fprintf(stderr, "epviz bench%s: %s\n", first && request.quick ? " --quick" : "",
                 line.c_str());
    first = false;
  };
  const auto t0 = std::chrono::steady_clock::now();
  const auto rows = study::bench_studies(opts, note);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::fputs(study::bench_tables(rows).c_str(), stdout);
  std::printf("\nbench finished in %.1f s\n", wall);
  write_outputs(request, rows, wall);
  return 0;
}

std::function<int()> add_bench_command(CLI::App& app) {
  auto request = std::make_shared<BenchRequest>();
  auto* cmd = app.add_subcommand(
      "bench", "Work-precision, invariant drift and stability studies of the methods");
  cmd->add_flag("--quick", request->quick, "a short study for CI (well under a minute)");
  cmd->add_option("--json", request->json, "write every row and the metadata to this JSON file");
  cmd->add_option("--out", request->out,
                  "create this directory and write bench.json and the charts (PNG) there");
  add_gl_option(*cmd, request->gl, "for the charts");
  cmd->add_option("--format", request->format,
                  "the charts' files with --out: png (GL), svg or pdf (cairo, vector; no GL "
                  "needed) (default png)");
  cmd->add_option("--cases", request->cases,
                  "comma-separated presets for the work-precision and drift studies (default all; "
                  "none with --job unless named; custom: the --job body)");
  cmd->add_option("--job", request->job,
                  "a render job (JSON) whose \"simulation\" gives a body of one's own: the "
                  "work-precision study runs on it too");
  return [request] { return run_bench(*request); };
}

}  // namespace epviz::app
