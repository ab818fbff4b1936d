#include "app/bench_command.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "app/gl_option.hpp"
#include "app/simulation_fields.hpp"
#include "app/text_table.hpp"
#include "io/atomic_file.hpp"
#include "io/bad_input.hpp"
#include "job/job_file.hpp"
#include "job/resolve.hpp"
#include "physics/cases.hpp"
#include "study/bench_json.hpp"
#include "study/invariant_cost.hpp"
#include "study/invariant_drift.hpp"
#include "study/peers/peer_study.hpp"
#include "study/pole_passage.hpp"
#include "study/stability.hpp"
#include "study/work_precision.hpp"
#ifdef EPVIZ_HAVE_RENDER
#include "io/png_writer.hpp"
#include "paint/figure_painter.hpp"
#include "render/gl_choice.hpp"
#include "study/bench_figures.hpp"
#include "vector/figure_format.hpp"
#include "vector/vector_figure.hpp"
#endif

namespace epviz::app {
namespace {

namespace fs = std::filesystem;
using namespace study;

std::string compiler() {
#if defined(__clang__)
  return std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  return std::string("gcc ") + __VERSION__;
#else
  return "unknown";
#endif
}

// --- Stage 1: the request, checked before any work ---------------------------

// The presets named by --cases; "custom" stands for the body of --job and
// is accepted only with it.
std::vector<physics::Case> parse_cases(const std::string& list, bool have_job) {
  std::vector<physics::Case> cases;
  if (list.empty()) return cases;
  std::stringstream s(list);
  std::string item;
  while (std::getline(s, item, ',')) {
    const auto c = physics::case_from_name(item);
    if (c == physics::Case::custom) {
      if (!have_job)
        throw io::BadInput(
            "--cases: 'custom' needs --job FILE (a render job whose \"simulation\" gives the "
            "body)");
      continue;
    }
    if (!c) {
      std::string names;
      for (const auto& p : physics::case_presets()) names += (names.empty() ? "" : ", ") + p.name;
      throw io::BadInput("--cases: unknown case '" + item +
                         "' (expected a comma-separated list of " + names +
                         (have_job ? ", custom" : "") + ")");
    }
    cases.push_back(*c);
  }
  return cases;
}

// The body and initial state of a render job's "simulation" (a single job),
// checked as `epviz render` checks them.
study::Problem job_problem(const std::string& file) {
  if (!fs::is_regular_file(file)) throw io::BadInput("--job: no such file '" + file + "'");
  const job::LoadedJob loaded = job::load_job_file(file);
  if (!loaded.single)
    throw io::BadInput("--job: '" + file +
                       "' is a gallery or bench-figures job; expected a single render job");
  const sim::RunSpec spec = job::resolve(loaded.single->simulation);
  study::Problem p;
  p.id = spec.case_id;
  p.name = spec.case_id == physics::Case::custom ? "custom" : physics::case_name(spec.case_id);
  p.body = spec.body;
  p.initial = spec.initial;
  return p;
}

// Checks where the outputs go and creates the --out directory.
void prepare_outputs(const BenchRequest& request) {
  if (!request.json.empty()) {
    const auto dir = fs::absolute(request.json).parent_path();
    if (!fs::is_directory(dir))
      throw io::BadInput("--json: directory '" + dir.string() + "' does not exist");
    if (fs::is_directory(request.json))
      throw io::BadInput("--json: '" + request.json + "' is a directory");
  }
  if (!request.out.empty()) {
    if (fs::exists(request.out) && !fs::is_directory(request.out))
      throw io::BadInput("--out: '" + request.out + "' exists and is not a directory");
    std::error_code ec;
    fs::create_directories(request.out, ec);
    if (ec)
      throw io::BadInput("--out: cannot create directory '" + request.out + "': " + ec.message());
  }
}

// --- Stage 2: the studies ------------------------------------------------------

std::vector<StudyRow> run_studies(const StudyOptions& opts) {
  std::vector<StudyRow> rows;
  std::fprintf(stderr, "epviz bench%s: work-precision...\n", opts.quick ? " --quick" : "");
  append(rows, work_precision_study(opts));
  std::fprintf(stderr, "epviz bench: peers (Boost.Odeint, GSL, SciPy where available)...\n");
  auto peer_study = peers::peer_work_precision_study(opts);
  for (const auto& line : peer_study.skipped)
    std::fprintf(stderr, "epviz bench: %s\n", line.c_str());
  append(rows, std::move(peer_study.rows));
  append(rows, peers::equal_error_ratios(rows_of<WorkPrecisionRow>(rows), {1e-6, 1e-8, 1e-10}));
  std::fprintf(stderr, "epviz bench: invariant drift...\n");
  append(rows, drift_study(opts));
  std::fprintf(stderr, "epviz bench: invariant cost...\n");
  append(rows, invariant_cost_study(opts));
  std::fprintf(stderr, "epviz bench: stability...\n");
  append(rows, stability_max_step(opts));
  append(rows, stability_pole(opts));
  append(rows, stability_separatrix(opts));
  append(rows, stability_sleeping(opts));
  append(rows, stability_chaos(opts));
  return rows;
}

// --- Stage 3: the tables -------------------------------------------------------

// Columns reading a field of the row, or of its RunRecord.
template <class Row>
TextColumn<Row> text(std::string header, std::string Row::*field) {
  return {std::move(header), [field](const Row& r) { return r.*field; }};
}
template <class Row, class T>
TextColumn<Row> number(std::string header, T Row::*field) {
  return {std::move(header), [field](const Row& r) { return cell_number(double(r.*field)); }};
}
template <class Row>
TextColumn<Row> flag(std::string header, bool Row::*field) {
  return {std::move(header),
          [field](const Row& r) { return std::string(r.*field ? "yes" : "no"); }};
}
template <class Row>
TextColumn<Row> run_text(std::string header, std::string RunRecord::*field) {
  return {std::move(header), [field](const Row& r) { return r.run.*field; }};
}
template <class Row, class T>
TextColumn<Row> run_number(std::string header, T RunRecord::*field) {
  return {std::move(header), [field](const Row& r) { return cell_number(double(r.run.*field)); }};
}
template <class Row>
TextColumn<Row> run_status(std::string header) {
  return {std::move(header), [](const Row& r) { return std::string(r.run.ok ? "ok" : "failed"); }};
}

void print_work_precision_tables(const std::vector<StudyRow>& rows) {
  using R = WorkPrecisionRow;
  TextTable<R> table{
      "",
      {run_text<R>("impl", &RunRecord::impl), run_text<R>("method", &RunRecord::method),
       run_text<R>("formulation", &RunRecord::formulation), run_number<R>("tol", &RunRecord::tol),
       run_number<R>("step", &RunRecord::step), number("error", &R::error),
       run_number<R>("rhs_evals", &RunRecord::rhs_evals),
       run_number<R>("flow_evals", &RunRecord::flow_evals),
       run_number<R>("cpu_ms", &RunRecord::cpu_ms), run_status<R>("status")}};
  const auto runs = rows_of<R>(rows);
  for (const auto* ref : rows_of<ReferenceRow>(rows)) {
    table.title =
        "work-precision: " + ref->case_name + " (t_end " + cell_number(ref->t_end) +
        "; error = |dOmega|_2 + |dgamma|_2 vs Gauss6 Richardson, self-check vs DOP853 1e-14: " +
        cell_number(ref->self_check) + ")";
    std::vector<const R*> of_case;
    std::copy_if(runs.begin(), runs.end(), std::back_inserter(of_case),
                 [&](const R* r) { return r->run.case_name == ref->case_name; });
    print_table(table, of_case);
  }
}

void print_peer_table(const std::vector<StudyRow>& rows) {
  using R = PeerRatioRow;
  print_table(
      TextTable<R>{
          "peers: CPU time against epviz dop853 at equal achieved error (log-log interpolation; "
          "ratio > 1: epviz is faster)",
          {text("case", &R::case_name), text("impl", &R::impl), text("method", &R::method),
           number("error", &R::error), number("peer_ms", &R::peer_cpu_ms),
           number("epviz_ms", &R::epviz_dop853_cpu_ms), number("ratio", &R::ratio)}},
      rows_of<R>(rows));
}

void print_invariant_tables(const std::vector<StudyRow>& rows) {
  {
    using R = DriftRow;
    print_table(
        TextTable<R>{
            "invariant drift (max relative, direct formulation, equal evaluations per time unit)",
            {run_text<R>("case", &RunRecord::case_name), run_text<R>("method", &RunRecord::method),
             run_number<R>("tol", &RunRecord::tol), run_number<R>("step", &RunRecord::step),
             run_number<R>("t_end", &RunRecord::t_end),
             run_number<R>("rhs_evals", &RunRecord::rhs_evals),
             run_number<R>("cpu_ms", &RunRecord::cpu_ms),
             number("|gamma|^2", &R::drift_gamma_norm2), number("C0", &R::drift_C0),
             number("C1", &R::drift_C1), number("extra", &R::drift_extra)}},
        rows_of<R>(rows));
  }
  using R = InvariantCostRow;
  const auto cost = rows_of<R>(rows);
  char title[160];
  std::snprintf(
      title, sizeof title,
      "invariant cost: cheapest run keeping C1 and the 4th integral within %g over T = %g "
      "(kovalevskaya, direct)",
      kInvariantCostTarget, cost.empty() ? 0.0 : cost[0]->run.t_end);
  print_table(TextTable<R>{title,
                           {run_text<R>("method", &RunRecord::method),
                            run_number<R>("tol", &RunRecord::tol),
                            run_number<R>("step", &RunRecord::step),
                            flag("reached", &R::reached),
                            {"cost", [](const R& r) { return cell_number(double(r.run.cost())); }},
                            run_number<R>("cpu_ms", &RunRecord::cpu_ms),
                            number("C1", &R::drift_C1),
                            number("extra", &R::drift_extra)}},
              cost);
}

void print_stability_tables(const std::vector<StudyRow>& rows) {
  {
    using R = MaxStepRow;
    print_table(TextTable<R>{"stability 1: largest fixed step before blow-up, lost motion "
                             "(energy or |gamma|^2 drift > 1) or loss of shape (error > 0.1)",
                             {text("case", &R::case_name), text("method", &R::method),
                              number("max_step", &R::max_step),
                              number("h/period", &R::max_step_over_period),
                              number("failing", &R::failing_step),
                              text("failure at the failing step", &R::failure_reason)}},
                rows_of<R>(rows));
  }
  {
    using R = PolePassageRow;
    print_table(
        TextTable<R>{
            "stability 2: south-pole passage, dop853 at equal tolerance",
            {text("variant", &R::variant),
             run_status<R>("status"),
             run_number<R>("fail_t", &RunRecord::failure_t),
             {"steps",
              [](const R& r) { return cell_number(r.run.steps ? double(*r.run.steps) : NAN); }},
             number("switches", &R::chart_switches),
             number("error", &R::error),
             run_text<R>("reason", &RunRecord::failure_reason)}},
        rows_of<R>(rows));
  }
  {
    using R = SeparatrixRow;
    print_table(
        TextTable<R>{
            "stability 3: Euler case near the separatrix, first flip of Omega_2",
            {run_text<R>("method", &RunRecord::method), run_number<R>("tol", &RunRecord::tol),
             run_number<R>("step", &RunRecord::step), number("flip_t", &R::flip_time),
             number("ref_flip_t", &R::reference_flip_time), number("|dt|", &R::flip_time_error),
             number("flips", &R::flips), number("ref", &R::reference_flips),
             number("|dt| last", &R::last_flip_time_error)}},
        rows_of<R>(rows));
  }
  {
    using R = SleepingTopRow;
    print_table(
        TextTable<R>{
            "stability 4: fast sleeping top (Omega3 = 50): cheapest run with gamma error < 1e-3",
            {run_text<R>("method", &RunRecord::method),
             run_text<R>("formulation", &RunRecord::formulation),
             run_number<R>("tol", &RunRecord::tol), run_number<R>("step", &RunRecord::step),
             flag("reached", &R::reached), number("gamma_err", &R::gamma_error),
             run_number<R>("rhs_evals", &RunRecord::rhs_evals),
             run_number<R>("cpu_ms", &RunRecord::cpu_ms)}},
        rows_of<R>(rows));
  }
  using R = ChaosRow;
  print_table(
      TextTable<R>{
          "stability 5: generic body from a strongly chaotic state (Lyapunov time ~2), time of "
          "separation > 1e-3 from the reference",
          {run_text<R>("method", &RunRecord::method), run_number<R>("tol", &RunRecord::tol),
           run_number<R>("step", &RunRecord::step), flag("separated", &R::separated),
           number("sep_time", &R::separation_time), run_number<R>("t_end", &RunRecord::t_end),
           run_number<R>("cpu_ms", &RunRecord::cpu_ms)}},
      rows_of<R>(rows));
}

// --- Stage 4: the JSON document and the charts --------------------------------

nlohmann::json bench_document(const std::vector<StudyRow>& rows, bool quick, double wall) {
  double worst_check = 0.0, smallest = INFINITY;
  for (const auto* r : rows_of<ReferenceRow>(rows)) {
    worst_check = std::max(worst_check, r->self_check);
    if (std::isfinite(r->smallest_error)) smallest = std::min(smallest, r->smallest_error);
  }
  nlohmann::json doc;
  doc["metadata"] = {
      {"tool", "epviz bench"},
      {"mode", quick ? "quick" : "full"},
      {"wall_seconds", wall},
      {"machine", {{"nproc", std::thread::hardware_concurrency()}, {"compiler", compiler()}}},
      {"error_measure", "|Omega - Omega_ref|_2 + |gamma - gamma_ref|_2 at the final time"},
      {"cost_measure", "rhs_evals (+ flow_evals: exact sub-flow evaluations of splitting methods)"},
      {"cpu_time", "median of repeated runs (repeats field), integration only, no I/O"},
      {"reference",
       {{"method", "gauss6 at steps h and h/2, Richardson-extrapolated: (64 y(h/2) - y(h)) / 63"},
        {"check", "dop853 at tol 1e-14"},
        {"max_self_check", worst_check},
        {"smallest_reported_error", number_or_null(smallest)}}},
  };
  doc["rows"] = rows_json(rows);
  return doc;
}

#ifdef EPVIZ_HAVE_RENDER
// Draws the bench's figures with epviz's own offscreen renderer, one PNG each,
// or with cairo, one SVG or PDF each (no GL needed).
std::size_t write_figures(const std::vector<StudyRow>& rows, const fs::path& out_dir,
                          const std::string& gl, vector::FigureFormat format) {
  const auto figures = bench_figures(rows);
  if (figures.empty()) return 0;
  if (format != vector::FigureFormat::png) {
    for (const auto& f : figures)
      vector::write_vector_figure(out_dir / vector::figure_file_name(f.file_name, format), f,
                                  format);
    return figures.size();
  }
  const auto context = render::GlChoice(gl).open();
  for (const auto& figure : figures) {
    const auto image = paint::paint_figure(*context, figure);
    io::write_png_rgba(out_dir / figure.file_name, image.width, image.height, image.pixels);
  }
  return figures.size();
}
#endif

void write_outputs(const BenchRequest& request, const std::vector<StudyRow>& rows, double wall) {
  if (request.json.empty() && request.out.empty()) return;
  const std::string text = bench_document(rows, request.quick, wall).dump(1) + "\n";
  if (!request.json.empty()) io::write_file_atomically(request.json, text);
  if (request.out.empty()) return;
  io::write_file_atomically(fs::path(request.out) / "bench.json", text);
#ifdef EPVIZ_HAVE_RENDER
  const std::size_t n =
      write_figures(rows, request.out, request.gl, vector::parse_figure_format(request.format));
  std::printf("%zu charts written to %s\n", n, request.out.c_str());
#endif
}

}  // namespace

int run_bench(const BenchRequest& request) {
  StudyOptions opts;
  opts.quick = request.quick;
  if (!request.job.empty()) opts.custom = job_problem(request.job);
  opts.cases = parse_cases(request.cases, !request.job.empty());
#ifdef EPVIZ_HAVE_RENDER
  (void)vector::parse_figure_format(request.format);  // before --out is created
#endif
  prepare_outputs(request);
#ifdef EPVIZ_HAVE_RENDER
  (void)render::GlChoice(request.gl);  // the charts come after every study: checked before
#endif
  const auto t0 = std::chrono::steady_clock::now();
  const auto rows = run_studies(opts);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  print_work_precision_tables(rows);
  print_peer_table(rows);
  print_invariant_tables(rows);
  print_stability_tables(rows);
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
