#include "app/simulate_command.hpp"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>

#include "app/cli_values.hpp"
#include "app/failure_advice.hpp"
#include "app/simulation_fields.hpp"
#include "app/simulation_output.hpp"
#include "app/usage_error.hpp"
#include "io/atomic_file.hpp"
#include "physics/cases.hpp"

namespace epviz::app {
namespace {

struct RawOptions {
  std::string job, csv, report_json;
  SimulationOptions sim;
};

SimulationFields fields_from_job(const std::string& path) {
  try {
    auto json = io::read_json_file(path);
    io::ObjectReader reader(json, path);
    auto f = read_simulation_fields(reader);
    reader.finish();
    return f;
  } catch (const io::JobError& e) {
    throw UsageError(e.what());
  }
}

void check_output_path(const std::string& option, const std::string& path) {
  if (path.empty()) return;
  const auto dir = std::filesystem::absolute(path).parent_path();
  if (!std::filesystem::is_directory(dir))
    throw UsageError(option + ": directory '" + dir.string() + "' does not exist");
}

std::string fmt(double x, const char* f = "%.3g") {
  char buf[32];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

void print_summary(const sim::RunSpec& spec, const sim::RunResult& r, const sim::Drifts& d) {
  std::string accuracy =
      sim::is_adaptive(spec.method) ? "tol " + fmt(spec.tol) : "step " + fmt(r.effective_step);
  std::printf("%-20s %-8s %-9s %-12s steps %8ld  rhs %9ld  rejected %5ld  cpu %8.4f s\n",
              physics::case_name(spec.case_id).c_str(),
              std::string(sim::name(spec.formulation)).c_str(),
              std::string(sim::name(spec.method)).c_str(), accuracy.c_str(), r.stats.steps,
              r.stats.rhs_evals, r.stats.rejected_steps, r.cpu_seconds);
  std::printf("%-20s max relative drift  |gamma|^2 %-9s  C0 %-9s  C1 %-9s  extra %s\n", "",
              fmt(d.gamma_norm2).c_str(), fmt(d.area).c_str(), fmt(d.energy).c_str(),
              d.extra ? fmt(*d.extra).c_str() : "-");
  if (r.failure) std::printf("%-20s FAILED: %s\n", "", failure_line(*r.failure).c_str());
}

int run_simulate(const RawOptions& raw) {
  SimulationFields fields;
  if (!raw.job.empty()) fields = fields_from_job(raw.job);
  fields.overlay(fields_from_options(raw.sim));
  require_distinct_files({{"--csv", raw.csv}, {"--report-json", raw.report_json}});
  check_output_path("--csv", raw.csv);
  check_output_path("--report-json", raw.report_json);

  std::vector<SimulationFields> runs;
  if (fields.case_name && *fields.case_name == "all") {
    if (!raw.csv.empty())
      throw UsageError("--csv: writes one run's samples; it cannot be combined with --case all");
    for (const auto& p : physics::case_presets()) {
      SimulationFields one = fields;
      one.case_name.set(p.name, fields.case_name.origin);
      runs.push_back(one);
    }
  } else {
    runs.push_back(fields);
  }

  // Resolve every run before integrating any: bad input leaves nothing behind.
  std::vector<sim::RunSpec> specs;
  for (const auto& f : runs) specs.push_back(resolve(f));

  nlohmann::json reports = nlohmann::json::array();
  int failures = 0;
  std::string csv;
  for (const auto& spec : specs) {
    const auto result = sim::simulate(spec);
    const sim::InvariantMonitor monitor(spec.body, spec.case_id, spec.initial);
    const auto drift = monitor.max_relative_drift(result.samples);
    print_summary(spec, result, drift);
    reports.push_back(run_report(spec, result, drift));
    if (!raw.csv.empty()) csv = samples_csv(spec, result);
    if (result.failure) {
      ++failures;
      std::fprintf(stderr, "epviz: %s\n", failure_line(*result.failure).c_str());
    }
  }
  if (!raw.csv.empty()) io::write_file_atomically(raw.csv, csv);
  if (!raw.report_json.empty())
    io::write_file_atomically(raw.report_json,
                              (specs.size() == 1 ? reports[0] : reports).dump(2) + "\n");
  return failures ? 3 : 0;
}

}  // namespace

std::function<int()> add_simulate_command(CLI::App& app) {
  auto raw = std::make_shared<RawOptions>();
  auto* cmd =
      app.add_subcommand("simulate", "Integrate one body (or every preset) and write samples");
  cmd->add_option("--job", raw->job,
                  "JSON job file with the same fields (options given here override it)");
  add_simulation_options(*cmd, raw->sim);
  cmd->add_option("--csv", raw->csv, "write the samples to this CSV file");
  cmd->add_option("--report-json", raw->report_json, "write the run report to this JSON file");
  return [raw] { return run_simulate(*raw); };
}

}  // namespace epviz::app
