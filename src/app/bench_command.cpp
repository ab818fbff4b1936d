#include "app/bench_command.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "app/cli_values.hpp"
#include "app/gl_option.hpp"
#include "app/print_options.hpp"
#include "io/atomic_file.hpp"
#include "io/bad_input.hpp"
#include "io/json_reader.hpp"
#include "io/json_text.hpp"
#include "io/output_paths.hpp"
#include "job/resolve.hpp"
#include "job/schema.hpp"
#include "study/bench_json.hpp"
#include "study/bench_studies.hpp"
#include "study/bench_tables.hpp"
#include "study/recommendation.hpp"
#ifdef EPVIZ_HAVE_RENDER
#include "render/gl_choice.hpp"
#include "study/bench_figures.hpp"
#include "vector/figure_files.hpp"
#endif

namespace epviz::app {
namespace {

namespace fs = std::filesystem;

// The body, initial state and final time of a job: a single render job's
// "simulation", or a simulate job (its fields at the top level), checked as
// `epviz render` and `epviz simulate` check them.
study::Problem job_problem(const std::string& file) {
  if (!fs::is_regular_file(file)) throw io::BadInput("--job: no such file '" + file + "'");
  const nlohmann::json json = io::read_json_file(file);
  if (json.contains("jobs") || json.contains("bench"))
    throw io::BadInput("--job: '" + file +
                       "' is a gallery or bench-figures job; expected a single render job or a "
                       "simulate job");
  job::SimulationFields fields;
  if (json.contains("simulation")) {
    fields = job::read_job(json, file).simulation;
  } else {
    io::ObjectReader reader(json, file);
    fields = job::read_simulation_fields(reader);
    reader.finish();
  }
  return study::run_problem(job::resolve(fields));
}

// --json may name a file in the folder that --out is about to make.
void check_json_path(const BenchRequest& request) {
  if (!request.out.empty() && !request.json.empty() && request.json.back() != '/') {
    std::error_code e1, e2, e3;
    const bool out_missing = !fs::exists(request.out, e1) && !e1;
    const fs::path json_dir = fs::weakly_canonical(fs::absolute(request.json).parent_path(), e2);
    const fs::path out = fs::weakly_canonical(fs::absolute(request.out), e3);
    if (out_missing && !e2 && !e3 && json_dir == out)
      return;  // check_output_dir has checked that the folder can be made
  }
  io::check_output_file("--json", request.json);
}

// --target-error: an error the references can judge (they agree to 1e-12 or
// better), with --job only.
double target_error(const BenchRequest& request) {
  if (request.target_error.empty()) return study::kDefaultTargetError;
  if (request.job.empty())
    throw io::BadInput("--target-error: needs --job FILE (the job the recommendation is for)");
  const double v = parse_number("--target-error", request.target_error);
  if (!(v >= 1e-13 && v <= 1.0))
    throw io::BadInput("--target-error: '" + request.target_error +
                       "' is outside 1e-13 to 1 (an error at t_end the reference can judge)");
  return v;
}

void write_outputs(const BenchRequest& request, const std::vector<study::StudyRow>& rows,
                   double wall, const std::optional<study::Recommendation>& recommendation,
                   const std::optional<io::PrintSize>& print) {
  if (request.json.empty() && request.out.empty()) return;
  const std::string text =
      io::json_text(study::bench_document(rows, request.quick, wall, recommendation), 1) + "\n";
  if (!request.json.empty()) io::write_file_atomically(request.json, text);
  if (request.out.empty()) return;
  io::write_file_atomically(fs::path(request.out) / "bench.json", text);
#ifdef EPVIZ_HAVE_RENDER
  // The charts' usual 1280 x 800, or that aspect at the printed size.
  const auto written = vector::write_figures(
      study::bench_figures(rows), request.out, vector::parse_figure_format(request.format),
      request.gl, chart_options({.width = 1280, .height = 800}, print));
  std::printf("%zu charts written to %s\n", written.size(), request.out.c_str());
#else
  (void)print;
#endif
}

}  // namespace

int run_bench(const BenchRequest& request) {
  // Every option is checked before the studies, which take minutes.
  study::StudyOptions opts;
  opts.quick = request.quick;
  if (!request.job.empty()) opts.custom = job_problem(request.job);
  opts.cases = study::parse_case_list(request.cases, !request.job.empty());
  const double target = target_error(request);
  const auto print = io::parse_print_size(request.print);
#ifdef EPVIZ_HAVE_RENDER
  (void)vector::parse_figure_format(request.format);
  (void)render::GlChoice(request.gl);
#endif
  if (!request.out.empty()) io::check_output_dir("--out", request.out);
  check_json_path(request);
  io::require_separate_files(
      {{"--job", request.job}},
      {{"--json", request.json},
       {"--out", request.out.empty() ? "" : (fs::path(request.out) / "bench.json").string()}});
  if (!request.out.empty()) io::make_output_folder("--out", request.out);

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
  std::optional<study::Recommendation> recommendation;
  if (opts.custom) {
    recommendation = study::recommend(*opts.custom, rows, target);
    std::printf("\n%s", study::recommendation_text(*recommendation).c_str());
  }
  std::printf("\nbench finished in %.1f s\n", wall);
  write_outputs(request, rows, wall, recommendation, print);
  return 0;
}

std::function<int()> add_bench_command(cli::Command app) {
  auto request = std::make_shared<BenchRequest>();
  cli::Command cmd = app.add_subcommand(
      "bench", "Work-precision, invariant drift and stability studies of the methods");
  cmd.add_flag("--quick", request->quick, "a short study for CI (well under a minute)");
  cmd.add_option("--json", request->json, "write every row and the metadata to this JSON file");
  cmd.add_option("--out", request->out,
                 "create this directory and write bench.json and the charts (PNG) there");
  add_gl_option(cmd, request->gl, "for the charts");
  cmd.add_option("--format", request->format,
                 "the charts' files with --out: png (GL), svg or pdf (cairo, vector; no GL "
                 "needed) (default png)");
  add_print_options(cmd, request->print);
  cmd.add_option("--cases", request->cases,
                 "comma-separated presets for the work-precision and drift studies (default all; "
                 "none with --job unless named; custom: the --job body)");
  cmd.add_option("--job", request->job,
                 "a render job (its \"simulation\") or a simulate job (JSON): the "
                 "work-precision study and the peers run on its body, initial state and t_end, "
                 "and the bench recommends a method for it");
  cmd.add_option("--target-error", request->target_error,
                 "with --job: the error at t_end the recommended method must reach (default "
                 "1e-8)");
  return [request] { return run_bench(*request); };
}

}  // namespace epviz::app
