#pragma once
// Strang splitting (symmetric composition of exact sub-flows), order 2, fixed
// step. The system provides n_flows exactly solvable sub-flows:
//
//   static constexpr int n_flows;
//   void flow(int i, double h, State& x) const;   // x <- exact flow i over time h
//
// One step of size h is
//   flow(0, h/2) ... flow(n-2, h/2) flow(n-1, h) flow(n-2, h/2) ... flow(0, h/2)
// (applied left to right). When every sub-flow preserves a quantity (e.g. a
// Casimir of a Lie–Poisson system), so does the method, up to round-off.
// The sub-flows are autonomous: t is used only for failure reports.
#include "numerics/stepper_common.hpp"

namespace epviz::numerics {

template <class Sys>
requires SplittableSystem<Sys>
class StrangSplitting : public StepperCore<Sys> {
  using StepperCore<Sys>::sys_;
  using StepperCore<Sys>::stats_;

 public:
  using System = Sys;
  using State = typename Sys::State;
  static constexpr const char* name = "splitting";
  static constexpr int order = 2;
  static constexpr int n_flows = Sys::n_flows;
  static_assert(n_flows >= 1, "a splitting needs at least one sub-flow");

  explicit StrangSplitting(Sys sys) : StepperCore<Sys>(std::move(sys)) {}

  // Advances x from t to t + h. Throws IntegrationError on a non-finite result
  // or when the system's check() objects; x is then left unchanged (apart from
  // a regularize() remapping at the start of the step).
  inline void step(State& x, double t, double h) {
    detail::regularize(sys_, x);
    tmp_ = x;
    const double h2 = 0.5 * h;
    for (int i = 0; i < n_flows - 1; ++i) sys_.flow(i, h2, tmp_);
    sys_.flow(n_flows - 1, h, tmp_);
    for (int i = n_flows - 2; i >= 0; --i) sys_.flow(i, h2, tmp_);
    stats_.flow_evals += 2 * n_flows - 1;
    this->accept(x, tmp_, t + h, name);
  }

 private:
  State tmp_ = State::Zero();
};

}  // namespace epviz::numerics
