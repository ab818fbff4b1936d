#include "app/simulation_fields.hpp"

#include <CLI/CLI.hpp>
#include <cmath>
#include <sstream>

#include "app/cli_values.hpp"
#include "app/usage_error.hpp"
#include "io/printable.hpp"
#include "physics/cases.hpp"

namespace epviz::app {
namespace {

Eigen::Vector3d to_vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

std::string case_names() {
  std::string s;
  for (const auto& p : physics::case_presets()) s += (s.empty() ? "" : ", ") + p.name;
  return s;
}

// Where a physics field name ("inertia") was given, for messages.
std::string origin_of(const SimulationFields& f, const std::string& field) {
  if (field == "inertia" && f.inertia) return f.inertia.origin;
  if (field == "com" && f.com) return f.com.origin;
  if (field == "weight" && f.weight) return f.weight.origin;
  if (field == "omega" && f.omega) return f.omega.origin;
  if (field == "gamma" && f.gamma) return f.gamma.origin;
  if (f.case_name) return f.case_name.origin;
  return "--" + field;
}

// How the user waives the check: the option on the command line, the key in a job.
std::string waiver_hint(physics::Waiver w, const std::string& origin) {
  const bool option = origin.starts_with("--");
  switch (w) {
    case physics::Waiver::none: return "";
    case physics::Waiver::allow_nonphysical:
      return option ? "; pass --allow-nonphysical to accept it"
                    : "; set \"allow_nonphysical\": true to accept it";
    case physics::Waiver::normalize_gamma:
      return option ? "; pass --normalize-gamma to rescale it"
                    : "; set \"normalize_gamma\": true to rescale it";
  }
  return "";  // not reached: every waiver is listed
}

}  // namespace

void add_simulation_options(CLI::App& cmd, SimulationOptions& o) {
  cmd.add_option("--case", o.case_name,
                 "euler|lagrange|kovalevskaya|goryachev-chaplygin|hess|generic, custom (no "
                 "case: your own body), or all");
  cmd.add_option("--inertia", o.inertia, "principal moments I1,I2,I3");
  cmd.add_option("--com", o.com, "centre of mass a0,b0,c0 in body axes");
  cmd.add_option("--weight", o.weight, "weight P = m g");
  cmd.add_option("--omega", o.omega, "initial angular velocity W1,W2,W3 (body axes)");
  cmd.add_option("--gamma", o.gamma, "initial unit vertical G1,G2,G3 (body axes)");
  cmd.add_option("--formulation", o.formulation,
                 sim::names_joined(sim::all_formulations()) + " (default direct)");
  cmd.add_option("--method", o.method, sim::names_joined(sim::all_methods()) + " (default dop853)");
  cmd.add_option("--tol", o.tol,
                 "relative and absolute tolerance of adaptive methods (default 1e-10)");
  cmd.add_option("--step", o.step, "largest step of fixed-step methods (default 0.01)");
  cmd.add_option("--t-end", o.t_end, "final time (default 20)");
  cmd.add_option("--samples", o.samples, "N: write N+1 equally spaced samples (default 200)");
  cmd.add_option("--max-drift", o.max_drift,
                 "fail (lost the motion) at the first sample whose relative energy or |gamma|^2 "
                 "drift exceeds X (default 1)");
  cmd.add_flag("--allow-nonphysical", o.allow_nonphysical,
               "accept moments that break the triangle inequalities");
  cmd.add_flag("--normalize-gamma", o.normalize_gamma, "rescale a non-unit initial gamma");
  cmd.add_flag("--no-chart-switch", o.no_chart_switch,
               "riccati: keep the north chart even near the south pole (to show the pole)");
}

SimulationFields fields_from_options(const SimulationOptions& o) {
  SimulationFields f;
  // The same bounds as the job's keys (job/schema.hpp).
  auto vec = [](Given<std::array<double, 3>>& g, const std::string& v, const char* opt, double lo,
                double hi) {
    if (v.empty()) return;
    const auto x = parse_vec3(opt, v);
    for (double c : x)
      if (!(c >= lo && c <= hi))
        throw UsageError(std::string(opt) + ": expected three numbers from " +
                         job::format_number(lo) + " to " + job::format_number(hi) + ", got '" +
                         io::printable(v) + "'");
    g.set(x, opt);
  };
  auto num = [](Given<double>& g, const std::string& v, const char* opt, bool positive,
                double max_abs = HUGE_VAL) {
    if (v.empty()) return;
    const double x = parse_number(opt, v);
    if (positive && !(x > 0.0))
      throw UsageError(std::string(opt) + ": expected a positive number, got '" + io::printable(v) +
                       "'");
    if (!(std::abs(x) <= max_abs))
      throw UsageError(std::string(opt) + ": expected a number from " +
                       job::format_number(-max_abs) + " to " + job::format_number(max_abs) +
                       ", got '" + io::printable(v) + "'");
    g.set(x, opt);
  };
  using job::max_magnitude;
  vec(f.inertia, o.inertia, "--inertia", job::min_moment, job::max_moment);
  vec(f.com, o.com, "--com", -max_magnitude, max_magnitude);
  vec(f.omega, o.omega, "--omega", -max_magnitude, max_magnitude);
  vec(f.gamma, o.gamma, "--gamma", -max_magnitude, max_magnitude);
  num(f.weight, o.weight, "--weight", false, max_magnitude);
  num(f.tol, o.tol, "--tol", true);
  num(f.step, o.step, "--step", true);
  num(f.t_end, o.t_end, "--t-end", true);
  num(f.max_drift, o.max_drift, "--max-drift", true);
  if (!o.case_name.empty()) f.case_name.set(o.case_name, "--case");
  if (!o.samples.empty())
    f.samples.set(parse_integer("--samples", o.samples, 1, job::max_samples), "--samples");
  if (!o.formulation.empty()) f.formulation.set(o.formulation, "--formulation");
  if (!o.method.empty()) f.method.set(o.method, "--method");
  if (o.allow_nonphysical) f.allow_nonphysical.set(true, "--allow-nonphysical");
  if (o.normalize_gamma) f.normalize_gamma.set(true, "--normalize-gamma");
  if (o.no_chart_switch) f.chart_switch.set(false, "--no-chart-switch");
  return f;
}

sim::RunSpec resolve(const SimulationFields& f) {
  sim::RunSpec spec;

  // The case: its preset is the starting point for every field not given.
  // "custom" (what a body without a case is called) is the same as no case.
  physics::Case c = physics::Case::custom;
  if (f.case_name) {
    auto found = physics::case_from_name(*f.case_name);
    if (!found)
      throw UsageError(f.case_name.origin + ": unknown case '" + io::printable(*f.case_name) +
                       "' (allowed: " + case_names() + ", custom)");
    c = *found;
  }
  const auto& p = physics::preset(c == physics::Case::custom ? physics::Case::generic : c);
  spec.case_id = c;
  spec.body = p.body;
  spec.initial = p.initial;
  if (f.inertia) spec.body.inertia = to_vec(*f.inertia);
  if (f.com) spec.body.com = to_vec(*f.com);
  if (f.weight) spec.body.weight = *f.weight;
  if (f.omega) spec.initial.omega = to_vec(*f.omega);
  if (f.gamma) spec.initial.gamma = to_vec(*f.gamma);

  if (f.formulation) {
    auto v = sim::formulation_from_name(*f.formulation);
    if (!v)
      throw UsageError(f.formulation.origin + ": unknown formulation '" +
                       io::printable(*f.formulation) +
                       "' (allowed: " + sim::names_joined(sim::all_formulations(), ", ") + ")");
    spec.formulation = *v;
  }
  if (f.method) {
    auto v = sim::method_from_name(*f.method);
    if (!v)
      throw UsageError(f.method.origin + ": unknown method '" + io::printable(*f.method) +
                       "' (allowed: " + sim::names_joined(sim::all_methods(), ", ") + ")");
    spec.method = *v;
  }
  if (auto why = sim::incompatibility(spec.method, spec.formulation))
    throw UsageError((f.method ? f.method.origin : f.formulation.origin) + ": " + *why);

  const std::string m(sim::name(spec.method));
  if (sim::is_adaptive(spec.method)) {
    if (f.step)
      throw UsageError(f.step.origin + ": method " + m +
                       " is adaptive and takes a tolerance (--tol), not a step");
    if (f.tol) spec.tol = *f.tol;
    if (!(spec.tol >= 1e-15 && spec.tol <= 1e-1))
      throw UsageError(f.tol.origin + ": tolerance must be between 1e-15 and 0.1, got " +
                       std::to_string(spec.tol));
  } else {
    if (f.tol)
      throw UsageError(f.tol.origin + ": method " + m +
                       " has a fixed step and takes --step, not a tolerance "
                       "(adaptive methods: " +
                       sim::names_joined(sim::adaptive_methods(), ", ") + ")");
    if (f.step) spec.step = *f.step;
  }
  if (f.chart_switch) {
    if (spec.formulation != sim::Formulation::riccati)
      throw UsageError(f.chart_switch.origin +
                       ": chart switching applies only to formulation riccati");
    spec.chart_switch = *f.chart_switch;
  }
  if (f.t_end) spec.t_end = *f.t_end;
  if (f.max_drift) spec.max_drift = *f.max_drift;
  if (f.samples) spec.samples = int(*f.samples);
  if (!sim::is_adaptive(spec.method) && spec.t_end / spec.step > 1e9)
    throw UsageError(f.step.origin + ": t_end / step exceeds 1e9 steps");

  try {
    physics::validate_body(spec.body, f.allow_nonphysical && *f.allow_nonphysical);
    spec.initial =
        physics::validate_initial_state(spec.initial, f.normalize_gamma && *f.normalize_gamma);
  } catch (const physics::InvalidInput& e) {
    const std::string origin = origin_of(f, e.field());
    throw UsageError(origin + ": " + e.what() + waiver_hint(e.waiver(), origin));
  }
  if (auto broken = physics::broken_condition(spec.case_id, spec.body, spec.initial))
    throw UsageError(f.case_name.origin + ": " + *broken +
                     " (for a nearby non-integrable body give no case, or case generic)");
  return spec;
}

}  // namespace epviz::app
