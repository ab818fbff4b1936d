#pragma once
// What one simulation run is: the body, its initial state, the formulation of
// the Poisson part, the integrator and its accuracy setting, and the output times.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "physics/body.hpp"
#include "physics/cases.hpp"
#include "sim/methods.hpp"

namespace epviz::sim {

std::string_view name(Formulation f);
std::string_view name(Method m);
std::optional<Formulation> formulation_from_name(std::string_view s);
std::optional<Method> method_from_name(std::string_view s);
const std::vector<Formulation>& all_formulations();
const std::vector<Method>& all_methods();
std::vector<Method> adaptive_methods();

bool is_adaptive(Method m);  // uses tol and dense output; the others use a fixed step
int order(Method m);         // classical order of the global error
// "rk4|dopri5|..." for help texts and error messages.
std::string names_joined(const std::vector<Method>& methods, std::string_view sep = "|");
std::string names_joined(const std::vector<Formulation>& formulations, std::string_view sep = "|");
// Why `m` cannot integrate formulation `f`, or nullopt (methods whose
// sub-flows are exact only in the direct formulation need it).
std::optional<std::string> incompatibility(Method m, Formulation f);

// The largest relative drift of the energy or of |gamma|^2 (physics/invariants.hpp
// defines the scales) that a run may reach before it counts as having lost the
// motion: 1, an error as large as the quantity itself (sim/drift.hpp checks it).
inline constexpr double kDefaultMaxDrift = 1.0;

struct RunSpec {
  physics::Case case_id = physics::Case::custom;
  physics::Body body;
  physics::InitialState initial;
  Formulation formulation = Formulation::direct;
  Method method = Method::dop853;
  double tol = 1e-10;  // adaptive methods: relative and absolute tolerance
  double step =
      1e-2;  // fixed-step methods: the step, taken exactly (outputs between steps interpolate)
  double t_end = 20.0;
  int samples = 200;             // samples + 1 equally spaced output times from 0 to t_end
  bool chart_switch = true;      // Riccati only: Moebius chart switch near the south pole
  long max_steps = 100'000'000;  // adaptive methods: step attempts before a step_budget failure
  // A run whose relative energy or |gamma|^2 drift exceeds this at an output
  // time fails there (numerics::FailureKind::lost_motion).
  double max_drift = kDefaultMaxDrift;
};

// The run of a body from an initial state with one method and formulation
// (`c`: the case it is, or custom); tol and step keep their defaults.
RunSpec body_run(physics::Case c, const physics::Body& body, const physics::InitialState& initial,
                 Method m, Formulation f, double t_end, int samples);
// The same for case `c`'s preset body and initial state.
RunSpec preset_run(physics::Case c, Method m, Formulation f, double t_end, int samples);

}  // namespace epviz::sim
