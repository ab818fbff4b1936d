#include "sweep/simulate_runs.hpp"

#include <cstdio>

#include "io/bad_input.hpp"
#include "job/render_report.hpp"
#include "job/resolve.hpp"
#include "physics/cases.hpp"
#include "sim/failure_advice.hpp"
#include "sweep/simulation_output.hpp"

namespace epviz::sweep {
namespace {

std::string fmt(double x, const char* f = "%.3g") {
  char buf[32];
  std::snprintf(buf, sizeof buf, f, x);
  return buf;
}

}  // namespace

bool runs_every_case(const job::SimulationFields& fields) {
  return fields.case_name && *fields.case_name == "all";
}

std::vector<sim::RunSpec> simulate_runs(const job::SimulationFields& fields,
                                        std::optional<long> max_steps) {
  std::vector<job::SimulationFields> runs;
  if (runs_every_case(fields)) {
    for (const auto& p : physics::case_presets()) {
      job::SimulationFields one = fields;
      one.case_name.set(p.name, fields.case_name.origin);
      runs.push_back(one);
    }
  } else {
    runs.push_back(fields);
  }
  std::vector<sim::RunSpec> specs;
  for (const auto& f : runs) specs.push_back(job::resolve(f));
  if (max_steps)
    for (auto& spec : specs) spec.max_steps = *max_steps;
  for (const auto& spec : specs) check_step_budget(spec);
  return specs;
}

void check_step_budget(const sim::RunSpec& spec) {
  if (sim::is_adaptive(spec.method)) return;
  const double steps = spec.t_end / spec.step;
  if (steps > double(spec.max_steps))
    throw io::BadInput("--t-end: " + fmt(spec.t_end) + " with --step " + fmt(spec.step) +
                       " needs " + fmt(steps) + " steps, more than the step budget of " +
                       fmt(double(spec.max_steps)) +
                       " (--max-steps); shorten --t-end or take a larger --step");
}

std::string run_summary(const sim::RunSpec& spec, const sim::RunResult& r,
                        const sim::RunDrifts& drifts) {
  const std::string accuracy =
      sim::is_adaptive(spec.method) ? "tol " + fmt(spec.tol) : "step " + fmt(r.effective_step);
  char line[512];
  std::snprintf(
      line, sizeof line, "%-20s %-8s %-9s %-12s steps %8ld  rhs %9ld  rejected %5ld  cpu %8.4f s\n",
      physics::case_name(spec.case_id).c_str(), std::string(sim::name(spec.formulation)).c_str(),
      std::string(sim::name(spec.method)).c_str(), accuracy.c_str(), r.stats.steps,
      r.stats.rhs_evals, r.stats.rejected_steps, r.cpu_seconds);
  std::string text = line;
  auto drift_line = [&](const char* name, const sim::Drifts& d) {
    std::snprintf(line, sizeof line, "%-20s %-18s  |gamma|^2 %-9s  C0 %-9s  C1 %-9s  extra %s\n",
                  "", name, fmt(d.gamma_norm2).c_str(), fmt(d.area).c_str(), fmt(d.energy).c_str(),
                  d.extra ? fmt(*d.extra).c_str() : "-");
    text += line;
  };
  drift_line("max relative drift", drifts.output);
  drift_line("step drift", drifts.steps);
  if (r.failure) {
    text += std::string(21, ' ');
    text += "FAILED: ";
    text += sim::failure_line(*r.failure, sim::SettingsIn::command_line);
    text += '\n';
  }
  return text;
}

nlohmann::json simulate_report(const sim::RunSpec& spec, const sim::RunResult& result,
                               const sim::RunDrifts& drifts) {
  nlohmann::json j = run_report(spec, result, drifts.output);
  j["step_drift"] = job::drift_json(drifts.steps);
  return j;
}

}  // namespace epviz::sweep
