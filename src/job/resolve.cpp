#include "job/resolve.hpp"

#include "io/bad_input.hpp"
#include "io/printable.hpp"
#include "job/fields.hpp"
#include "job/schema.hpp"
#include "physics/cases.hpp"

namespace epviz::job {

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

sim::RunSpec resolve(const SimulationFields& f) {
  sim::RunSpec spec;

  // The case: its preset is the starting point for every field not given.
  // "custom" (what a body without a case is called) is the same as no case.
  physics::Case c = physics::Case::custom;
  if (f.case_name) {
    auto found = physics::case_from_name(*f.case_name);
    if (!found)
      throw io::BadInput(f.case_name.origin + ": unknown case '" + io::printable(*f.case_name) +
                         "' (allowed: " + find_field("case")->choices + ")");
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
      throw io::BadInput(f.formulation.origin + ": unknown formulation '" +
                         io::printable(*f.formulation) +
                         "' (allowed: " + sim::names_joined(sim::all_formulations(), ", ") + ")");
    spec.formulation = *v;
  }
  if (f.method) {
    auto v = sim::method_from_name(*f.method);
    if (!v)
      throw io::BadInput(f.method.origin + ": unknown method '" + io::printable(*f.method) +
                         "' (allowed: " + sim::names_joined(sim::all_methods(), ", ") + ")");
    spec.method = *v;
  }
  if (auto why = sim::incompatibility(spec.method, spec.formulation))
    throw io::BadInput((f.method ? f.method.origin : f.formulation.origin) + ": " + *why);

  const std::string m(sim::name(spec.method));
  if (sim::is_adaptive(spec.method)) {
    if (f.step)
      throw io::BadInput(f.step.origin + ": method " + m +
                         " is adaptive and takes a tolerance (--tol), not a step");
    if (f.tol) spec.tol = *f.tol;  // in range: the field table's bounds hold where it is read
  } else {
    if (f.tol)
      throw io::BadInput(f.tol.origin + ": method " + m +
                         " has a fixed step and takes --step, not a tolerance "
                         "(adaptive methods: " +
                         sim::names_joined(sim::adaptive_methods(), ", ") + ")");
    if (f.step) spec.step = *f.step;
  }
  if (f.chart_switch) {
    if (spec.formulation != sim::Formulation::riccati)
      throw io::BadInput(f.chart_switch.origin +
                         ": chart switching applies only to formulation riccati");
    spec.chart_switch = *f.chart_switch;
  }
  if (f.t_end) spec.t_end = *f.t_end;
  if (f.max_drift) spec.max_drift = *f.max_drift;
  if (f.samples) spec.samples = int(*f.samples);
  if (!sim::is_adaptive(spec.method) && spec.t_end / spec.step > max_steps_per_run)
    throw io::BadInput(f.step.origin + ": t_end / step exceeds " +
                       format_number(max_steps_per_run) + " steps");

  try {
    physics::validate_body(spec.body, f.allow_nonphysical && *f.allow_nonphysical);
    spec.initial =
        physics::validate_initial_state(spec.initial, f.normalize_gamma && *f.normalize_gamma);
  } catch (const physics::InvalidInput& e) {
    const std::string origin = origin_of(f, e.field());
    throw io::BadInput(origin + ": " + e.what() + waiver_hint(e.waiver(), origin));
  }
  if (auto broken = physics::broken_condition(spec.case_id, spec.body, spec.initial))
    throw io::BadInput(f.case_name.origin + ": " + *broken +
                       " (for a nearby non-integrable body give no case, or case generic)");
  return spec;
}

}  // namespace epviz::job
