#include "app/simulation_fields.hpp"

#include <CLI/CLI.hpp>
#include <cmath>
#include <sstream>
#include <variant>

#include "app/cli_values.hpp"
#include "app/usage_error.hpp"
#include "io/printable.hpp"
#include "physics/cases.hpp"

namespace epviz::app {
namespace {

Eigen::Vector3d to_vec(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

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
  const auto& table = job::simulation_field_table();
  for (std::size_t i = 0; i < table.size(); ++i) {
    const auto& f = table[i];
    if (f.type == job::FieldType::flag) {
      cmd.add_flag(f.flag, o.values[i].set, f.help);
      continue;
    }
    std::string help = f.help;
    if (!f.choices.empty()) help += ": " + f.choices;
    if (f.key == "case") help += "; all: every preset";  // simulate runs each in turn
    if (const auto range = f.range_text(); !range.empty()) help += " (" + range + ")";
    if (!f.default_value.empty()) help += " (default " + f.default_value + ")";
    cmd.add_option(f.flag, o.values[i].text, help);
  }
}

namespace {

// The value of one option into its field, converted and checked against the
// field's range as the job's key is.
void set_from_option(const job::FieldInfo& f, const SimulationOptions::Value& v,
                     Given<std::string>& g) {
  if (!v.text.empty()) g.set(v.text, f.flag);
}
// Each of `numbers`, read from `text`, within the field's range.
template <class Numbers>
void require_in_range(const job::FieldInfo& f, const std::string& text, const Numbers& numbers) {
  for (double x : numbers)
    if (!f.in_range(x))
      throw UsageError(f.flag + ": expected " + f.range_text() + ", got '" + io::printable(text) +
                       "'");
}
void set_from_option(const job::FieldInfo& f, const SimulationOptions::Value& v,
                     Given<std::array<double, 3>>& g) {
  if (v.text.empty()) return;
  const auto x = parse_vec3(f.flag, v.text);
  require_in_range(f, v.text, x);
  g.set(x, f.flag);
}
void set_from_option(const job::FieldInfo& f, const SimulationOptions::Value& v, Given<double>& g) {
  if (v.text.empty()) return;
  const double x = parse_number(f.flag, v.text);
  require_in_range(f, v.text, std::array<double, 1>{x});
  g.set(x, f.flag);
}
void set_from_option(const job::FieldInfo& f, const SimulationOptions::Value& v, Given<long>& g) {
  if (!v.text.empty()) g.set(parse_integer(f.flag, v.text, long(f.min), long(f.max)), f.flag);
}
void set_from_option(const job::FieldInfo& f, const SimulationOptions::Value& v, Given<bool>& g) {
  if (v.set) g.set(f.flag_sets, f.flag);
}

}  // namespace

SimulationFields fields_from_options(const SimulationOptions& o) {
  SimulationFields fields;
  const auto& table = job::simulation_field_table();
  for (std::size_t i = 0; i < table.size(); ++i)
    std::visit([&](auto m) { set_from_option(table[i], o.values[i], fields.*m); }, table[i].member);
  return fields;
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
                       "' (allowed: " + job::find_field("case")->choices + ")");
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
    if (f.tol) spec.tol = *f.tol;  // in range: the field table's bounds hold where it is read
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
  if (!sim::is_adaptive(spec.method) && spec.t_end / spec.step > job::max_steps_per_run)
    throw UsageError(f.step.origin + ": t_end / step exceeds " +
                     job::format_number(job::max_steps_per_run) + " steps");

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
