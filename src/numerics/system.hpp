#pragma once
// The contract between an ODE system and the steppers.
//
// A system is a plain value type:
//
//   struct MySystem {
//     static constexpr int dim = N;
//     using State = Eigen::Matrix<double, N, 1>;
//     void rhs(double t, const State& x, State& dxdt) const;   // required
//
//     // Optional: called by every stepper at the start of each step. Returns
//     // true when it remapped the state (e.g. a Riccati chart switch); the
//     // stepper then drops any derivative it cached (FSAL). Because it runs at
//     // the start of a step, the dense output of the step that just finished
//     // is still expressed in the chart the system held during that step.
//     bool regularize(State& x);
//
//     // Optional: why the state cannot be trusted (e.g. a Riccati pole),
//     // checked after every accepted step; std::nullopt when fine.
//     std::optional<Issue> check(const State& x) const;
//   };
//
// Non-finite states are detected by the steppers themselves.
#include <Eigen/Core>
#include <optional>
#include <string>

#include "numerics/failure.hpp"

namespace epviz::numerics {

template <int N>
using Vec = Eigen::Matrix<double, N, 1>;

// What a system's check() reports: the kind of trouble and the plain fact
// (the stepper adds its name and the time to make a Failure).
struct Issue {
  FailureKind kind = FailureKind::chart_pole;
  std::string detail;
};

// Work counters every stepper keeps.
struct Stats {
  long steps = 0;              // accepted steps
  long rejected_steps = 0;     // adaptive methods only
  long rhs_evals = 0;          // right-hand side evaluations
  long solver_iterations = 0;  // implicit methods: total fixed-point/Newton iterations
  long flow_evals = 0;         // splitting methods: exact sub-flow evaluations
};

template <class Sys>
concept OdeSystem = requires(const Sys& s, double t, const typename Sys::State& x,
                             typename Sys::State& dx) {
  { Sys::dim } -> std::convertible_to<int>;
  s.rhs(t, x, dx);
};

namespace detail {

template <class Sys>
bool regularize(Sys& sys, typename Sys::State& x) {
  if constexpr (requires {
                  { sys.regularize(x) } -> std::convertible_to<bool>;
                })
    return sys.regularize(x);
  else
    return false;
}

template <class Sys>
std::optional<Issue> check(const Sys& sys, const typename Sys::State& x) {
  if constexpr (requires { sys.check(x); })
    return sys.check(x);
  else
    return std::nullopt;
}

}  // namespace detail
}  // namespace epviz::numerics
