#pragma once
// The one place where a run's Method becomes a stepper for a system: every
// path that integrates a single run (sim::Trajectory for simulate, render and
// serve; the Poincaré sections) builds its stepper here, with the options of
// sim/run_options.hpp. Adding an integrator adds one case to this switch, and
// a line to the list of out-of-line steppers below when its step is out of
// line.
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "numerics/composition.hpp"
#include "numerics/embedded_rk.hpp"
#include "numerics/gauss_legendre.hpp"
#include "numerics/rk4.hpp"
#include "numerics/splitting.hpp"
#include "physics/direct.hpp"
#include "physics/free_rigid_body_flow.hpp"
#include "sim/run_options.hpp"

namespace epviz::sim {

// An adaptive stepper (init/step/dense, its own step size), as opposed to a
// fixed-step one (step(x, t, h)).
template <class Stepper>
concept AdaptiveStepper = requires(const Stepper& s, double t) {
  s.dense(t);
};

// Calls `visit` with the stepper of spec.method for `sys` (moved in) and
// returns what it returns; every call must return one type. The exact
// splittings integrate the direct state split into a kick and the exact free
// rigid body flow, so they exist only for `sys` of the direct formulation.
// Throws std::invalid_argument when the method cannot integrate `sys`
// (sim::incompatibility says why).
template <class Sys, class Visit>
decltype(auto) with_stepper(Sys sys, const RunSpec& spec, Visit&& visit) {
  switch (spec.method) {
    case Method::rk4: return visit(numerics::Rk4<Sys>(std::move(sys)));
    case Method::dopri5:
      return visit(numerics::Dopri5<Sys>(std::move(sys), adaptive_options(spec)));
    case Method::dop853:
      return visit(numerics::Dop853<Sys>(std::move(sys), adaptive_options(spec)));
    case Method::midpoint: return visit(numerics::ImplicitMidpoint<Sys>(std::move(sys)));
    case Method::gauss4: return visit(numerics::Gauss4<Sys>(std::move(sys)));
    case Method::gauss6: return visit(numerics::Gauss6<Sys>(std::move(sys)));
    case Method::splitting:
      if constexpr (requires { Sys::n_flows; })
        return visit(numerics::StrangSplitting<Sys>(std::move(sys)));
      break;
    case Method::exact_split2:
      if constexpr (std::is_same_v<Sys, physics::DirectSystem>)
        return visit(numerics::Composition2<physics::ExactSplitSystem>(
            physics::ExactSplitSystem(spec.body), "exact-split2"));
      break;
    case Method::exact_split4:
      if constexpr (std::is_same_v<Sys, physics::DirectSystem>)
        return visit(numerics::Composition4<physics::ExactSplitSystem>(
            physics::ExactSplitSystem(spec.body), "exact-split4"));
      break;
  }
  throw std::invalid_argument(
      incompatibility(spec.method, spec.formulation).value_or("unknown method"));
}

}  // namespace epviz::sim

// The steppers whose step lives out of line (the adaptive Runge–Kutta pairs
// and the implicit Gauss–Legendre methods) for the direct formulation's
// system are compiled once, in steppers_direct.cpp (EPVIZ_SIM_INSTANTIATE_STEPPERS),
// and declared extern here: the trajectories, the sections and the tests,
// which all run them, link that copy instead of compiling their own. (The
// other formulations' steppers run only in their trajectory file, which
// instantiates them as it uses them; declaring them here would make every
// includer parse their systems' headers, which cost more than it saved.) The
// steppers whose step is written in the class (RK4, the splittings, the
// compositions) are inlined where they are used and need no entry.
// X(stepper type) for each of system Sys; a macro, not a type list, because
// an explicit instantiation has to spell its class out.
#define EPVIZ_SIM_OUT_OF_LINE_STEPPERS(X, Sys)                            \
  X(::epviz::numerics::EmbeddedRk<Sys, ::epviz::numerics::Dopri5Tableau>) \
  X(::epviz::numerics::EmbeddedRk<Sys, ::epviz::numerics::Dop853Tableau>) \
  X(::epviz::numerics::GaussLegendre<Sys, 1>)                             \
  X(::epviz::numerics::GaussLegendre<Sys, 2>)                             \
  X(::epviz::numerics::GaussLegendre<Sys, 3>)

#define EPVIZ_SIM_EXTERN_STEPPER(...) extern template class __VA_ARGS__;
#define EPVIZ_SIM_DEFINE_STEPPER(...) template class __VA_ARGS__;

EPVIZ_SIM_OUT_OF_LINE_STEPPERS(EPVIZ_SIM_EXTERN_STEPPER, ::epviz::physics::DirectSystem)

// In steppers_direct.cpp only, at file scope: the one definition of each.
#define EPVIZ_SIM_INSTANTIATE_STEPPERS(Sys) \
  EPVIZ_SIM_OUT_OF_LINE_STEPPERS(EPVIZ_SIM_DEFINE_STEPPER, Sys)
