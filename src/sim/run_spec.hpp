#pragma once
// What one simulation run is: the body, its initial state, the formulation of
// the Poisson part, the integrator and its accuracy setting, and the output times.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "physics/body.hpp"
#include "physics/cases.hpp"

namespace epviz::sim {

enum class Formulation { direct, riccati, spinor };
enum class Method { rk4, dopri5, dop853, midpoint, gauss4, gauss6, splitting, exact_split2, exact_split4 };

std::string_view name(Formulation f);
std::string_view name(Method m);
std::optional<Formulation> formulation_from_name(std::string_view s);
std::optional<Method> method_from_name(std::string_view s);
const std::vector<Formulation>& all_formulations();
const std::vector<Method>& all_methods();

bool is_adaptive(Method m);  // dopri5, dop853: use tol; the others use a fixed step
// Why `m` cannot integrate formulation `f`, or nullopt (splitting, exact-split2
// and exact-split4 need the direct formulation's exact sub-flows).
std::optional<std::string> incompatibility(Method m, Formulation f);

struct RunSpec {
  physics::Case case_id = physics::Case::custom;
  physics::Body body;
  physics::InitialState initial;
  Formulation formulation = Formulation::direct;
  Method method = Method::dop853;
  double tol = 1e-10;   // adaptive methods: relative and absolute tolerance
  double step = 1e-2;   // fixed-step methods: largest step; shortened so that it divides the sample spacing
  double t_end = 20.0;
  int samples = 200;    // samples + 1 equally spaced output times from 0 to t_end
  bool chart_switch = true;  // Riccati only: Moebius chart switch near the south pole
};

// The run of case `c`'s preset body and initial state with one method and
// formulation; tol and step keep their defaults.
RunSpec preset_run(physics::Case c, Method m, Formulation f, double t_end, int samples);

}  // namespace epviz::sim
