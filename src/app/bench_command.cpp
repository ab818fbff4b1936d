#include "app/bench_command.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "app/usage_error.hpp"
#include "io/atomic_file.hpp"
#include "physics/cases.hpp"
#include "sim/study_bench.hpp"
#ifdef EPVIZ_HAVE_PEERS
#include "peers/peer_study.hpp"
#endif
#ifdef EPVIZ_HAVE_RENDER
#include "paint/bench_charts.hpp"
#include "render/gl_context.hpp"
#endif

namespace epviz::app {
namespace {

using RawOptions = BenchRequest;

std::string compiler() {
#if defined(__clang__)
  return std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  return std::string("gcc ") + __VERSION__;
#else
  return "unknown";
#endif
}

nlohmann::json number_or_null(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

nlohmann::json row_json(const sim::StudyRow& r) {
  nlohmann::json j;
  j["study"] = r.study;
  for (const auto& [k, v] : r.text) j[k] = v;
  for (const auto& [k, v] : r.numbers) j[k] = number_or_null(v);
  for (const auto& [k, v] : r.series) {
    auto a = nlohmann::json::array();
    for (double x : v) a.push_back(number_or_null(x));
    j[k] = a;
  }
  return j;
}

// One table column: a header, the row's field, and how wide.
struct Column {
  const char* header;
  const char* key;
  int width;
};

std::string cell(const sim::StudyRow& r, const Column& c) {
  if (auto t = r.text_of(c.key)) return *t;
  if (auto x = r.number(c.key)) {
    if (!std::isfinite(*x)) return "-";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.3g", *x);
    return buf;
  }
  return "-";
}

void print_table(const std::string& title, const std::vector<const sim::StudyRow*>& rows,
                 const std::vector<Column>& cols) {
  if (rows.empty()) return;
  std::printf("\n%s\n", title.c_str());
  for (const auto& c : cols) std::printf("%-*s ", c.width, c.header);
  std::printf("\n");
  for (const auto* r : rows) {
    for (const auto& c : cols) std::printf("%-*s ", c.width, cell(*r, c).c_str());
    std::printf("\n");
  }
}

std::vector<const sim::StudyRow*> select(const std::vector<sim::StudyRow>& rows, const std::string& study,
                                         const std::string& case_name = "") {
  std::vector<const sim::StudyRow*> out;
  for (const auto& r : rows)
    if (r.study == study && (case_name.empty() || r.text_of("case") == case_name)) out.push_back(&r);
  return out;
}

std::vector<physics::Case> parse_cases(const std::string& list) {
  std::vector<physics::Case> cases;
  if (list.empty()) return cases;
  std::stringstream s(list);
  std::string item;
  while (std::getline(s, item, ',')) {
    const auto c = physics::case_from_name(item);
    if (!c || *c == physics::Case::custom) {
      std::string names;
      for (const auto& p : physics::case_presets()) names += (names.empty() ? "" : ", ") + p.name;
      throw UsageError("--cases: unknown case '" + item + "' (expected a comma-separated list of " + names + ")");
    }
    cases.push_back(*c);
  }
  return cases;
}

}  // namespace

int run_bench(const BenchRequest& raw) {
  sim::StudyOptions opts;
  opts.quick = raw.quick;
  opts.cases = parse_cases(raw.cases);
  namespace fs = std::filesystem;
  if (!raw.json.empty()) {
    const auto dir = fs::absolute(raw.json).parent_path();
    if (!fs::is_directory(dir)) throw UsageError("--json: directory '" + dir.string() + "' does not exist");
    if (fs::is_directory(raw.json)) throw UsageError("--json: '" + raw.json + "' is a directory");
  }
  if (!raw.out.empty()) {
    if (fs::exists(raw.out) && !fs::is_directory(raw.out))
      throw UsageError("--out: '" + raw.out + "' exists and is not a directory");
    std::error_code ec;
    fs::create_directories(raw.out, ec);
    if (ec) throw UsageError("--out: cannot create directory '" + raw.out + "': " + ec.message());
  }

  const auto t0 = std::chrono::steady_clock::now();
  std::vector<sim::StudyRow> rows;
  auto add = [&](std::vector<sim::StudyRow> more) {
    for (auto& r : more) rows.push_back(std::move(r));
  };
  std::fprintf(stderr, "epviz bench%s: work-precision...\n", raw.quick ? " --quick" : "");
  add(sim::work_precision_study(opts));
#ifdef EPVIZ_HAVE_PEERS
  std::fprintf(stderr, "epviz bench: peers (Boost.Odeint, GSL, SciPy)...\n");
  auto peer_study = peers::peer_work_precision_study(opts);
  for (const auto& line : peer_study.skipped) std::fprintf(stderr, "epviz bench: %s\n", line.c_str());
  add(std::move(peer_study.rows));
  add(peers::equal_error_ratios(rows, {1e-6, 1e-8, 1e-10}));
#endif
  std::fprintf(stderr, "epviz bench: invariant drift...\n");
  add(sim::drift_study(opts));
  std::fprintf(stderr, "epviz bench: invariant cost...\n");
  add(sim::invariant_cost_study(opts));
  std::fprintf(stderr, "epviz bench: stability...\n");
  add(sim::stability_max_step(opts));
  add(sim::stability_pole(opts));
  add(sim::stability_separatrix(opts));
  add(sim::stability_sleeping(opts));
  add(sim::stability_chaos(opts));
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  // Tables.
  const std::vector<Column> wp{{"impl", "impl", 12}, {"method", "method", 17}, {"formulation", "formulation", 11},
                               {"tol", "tol", 8},        {"step", "step", 9},
                               {"error", "error", 9},    {"rhs_evals", "rhs_evals", 10},
                               {"flow_evals", "flow_evals", 10}, {"cpu_ms", "cpu_ms", 9},
                               {"status", "status", 6}};
  for (const auto& p : physics::case_presets()) {
    const auto ref = select(rows, "reference", p.name);
    if (ref.empty()) continue;
    print_table("work-precision: " + p.name + " (t_end " + cell(*ref[0], {"", "t_end", 0}) +
                    "; error = |dOmega|_2 + |dgamma|_2 vs Gauss6 Richardson, self-check vs DOP853 1e-14: " +
                    cell(*ref[0], {"", "self_check", 0}) + ")",
                select(rows, "work_precision", p.name), wp);
  }
  print_table("peers: CPU time against epviz dop853 at equal achieved error (log-log interpolation; ratio > 1: "
              "epviz is faster)",
              select(rows, "peer_ratio"),
              {{"case", "case", 20}, {"impl", "impl", 12}, {"method", "method", 17}, {"error", "error", 9},
               {"peer_ms", "peer_cpu_ms", 9}, {"epviz_ms", "epviz_dop853_cpu_ms", 9}, {"ratio", "ratio", 8}});
  print_table("invariant drift (max relative, direct formulation, equal evaluations per time unit)",
              select(rows, "drift"),
              {{"case", "case", 20}, {"method", "method", 10}, {"tol", "tol", 8}, {"step", "step", 9},
               {"t_end", "t_end", 7}, {"rhs_evals", "rhs_evals", 10}, {"cpu_ms", "cpu_ms", 9},
               {"|gamma|^2", "drift_gamma_norm2", 9}, {"C0", "drift_C0", 9}, {"C1", "drift_C1", 9},
               {"extra", "drift_extra", 9}});
  {
    const auto ic = select(rows, "invariant_cost");
    char title[160];
    std::snprintf(title, sizeof title,
                  "invariant cost: cheapest run keeping C1 and the 4th integral within %g over T = %g "
                  "(kovalevskaya, direct)",
                  sim::kInvariantCostTarget, ic.empty() ? 0.0 : ic[0]->number("t_end").value_or(0.0));
    print_table(title, ic,
                {{"method", "method", 12}, {"tol", "tol", 8}, {"step", "step", 9}, {"reached", "reached", 7},
                 {"cost", "cost", 10}, {"cpu_ms", "cpu_ms", 9}, {"C1", "drift_C1", 9},
                 {"extra", "drift_extra", 9}});
  }
  print_table("stability 1: largest fixed step before blow-up or loss of shape (error > 0.1 or energy drift > 10%)",
              select(rows, "stability_max_step"),
              {{"case", "case", 13}, {"method", "method", 10}, {"max_step", "max_step", 9},
               {"h/period", "max_step_over_period", 9}, {"failing", "failing_step", 9},
               {"failure at the failing step", "failure_reason", 40}});
  print_table("stability 2: south-pole passage, dop853 at equal tolerance", select(rows, "stability_pole"),
              {{"variant", "variant", 21}, {"status", "status", 7}, {"fail_t", "failure_t", 8},
               {"steps", "steps", 7}, {"switches", "chart_switches", 8}, {"error", "error", 9},
               {"reason", "failure_reason", 40}});
  print_table("stability 3: Euler case near the separatrix, first flip of Omega_2",
              select(rows, "stability_separatrix"),
              {{"method", "method", 10}, {"tol", "tol", 8}, {"step", "step", 9}, {"flip_t", "flip_time", 9},
               {"ref_flip_t", "reference_flip_time", 10}, {"|dt|", "flip_time_error", 9},
               {"flips", "flips", 5}, {"ref", "reference_flips", 4}, {"|dt| last", "last_flip_time_error", 9}});
  print_table("stability 4: fast sleeping top (Omega3 = 50): cheapest run with gamma error < 1e-3",
              select(rows, "stability_sleeping_top"),
              {{"method", "method", 10}, {"formulation", "formulation", 11}, {"tol", "tol", 8},
               {"step", "step", 9}, {"reached", "reached", 7}, {"gamma_err", "gamma_error", 9},
               {"rhs_evals", "rhs_evals", 10}, {"cpu_ms", "cpu_ms", 9}});
  print_table("stability 5: generic body from a strongly chaotic state (Lyapunov time ~2), time of separation > 1e-3 from the reference",
              select(rows, "stability_chaos"),
              {{"method", "method", 10}, {"tol", "tol", 8}, {"step", "step", 9},
               {"separated", "separated", 9}, {"sep_time", "separation_time", 9}, {"t_end", "t_end", 6},
               {"cpu_ms", "cpu_ms", 9}});
  std::printf("\nbench finished in %.1f s\n", wall);

  if (raw.json.empty() && raw.out.empty()) return 0;
  nlohmann::json doc;
  double worst_check = 0.0, smallest = INFINITY;
  for (const auto* r : select(rows, "reference")) {
    worst_check = std::max(worst_check, r->number("self_check").value_or(0.0));
    const double s = r->number("smallest_error").value_or(NAN);
    if (std::isfinite(s)) smallest = std::min(smallest, s);
  }
  doc["metadata"] = {
      {"tool", "epviz bench"},
      {"mode", raw.quick ? "quick" : "full"},
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
  auto arr = nlohmann::json::array();
  for (const auto& r : rows) arr.push_back(row_json(r));
  doc["rows"] = arr;
  const std::string text = doc.dump(1) + "\n";
  if (!raw.json.empty()) io::write_file_atomically(raw.json, text);
  if (!raw.out.empty()) {
    io::write_file_atomically(fs::path(raw.out) / "bench.json", text);
#ifdef EPVIZ_HAVE_RENDER
    // The charts are drawn by epviz's own offscreen renderer.
    const std::string backend = raw.gl.empty() ? render::gl_backend_from_environment() : raw.gl;
    const auto charts = paint::write_bench_charts(doc, raw.out, backend);
    std::printf("%zu charts written to %s\n", charts.size(), raw.out.c_str());
#endif
  }
  return 0;
}

std::function<int()> add_bench_command(CLI::App& app) {
  auto raw = std::make_shared<RawOptions>();
  auto* cmd = app.add_subcommand("bench", "Work-precision, invariant drift and stability studies of the methods");
  cmd->add_flag("--quick", raw->quick, "a short study for CI (well under a minute)");
  cmd->add_option("--json", raw->json, "write every row and the metadata to this JSON file");
  cmd->add_option("--out", raw->out, "create this directory and write bench.json and the charts (PNG) there");
  cmd->add_option("--gl", raw->gl, "offscreen GL backend for the charts: auto, egl or osmesa (default: $EPVIZ_GL or auto)");
  cmd->add_option("--cases", raw->cases,
                  "comma-separated presets for the work-precision and drift studies (default all)");
  return [raw] { return run_bench(*raw); };
}

}  // namespace epviz::app
