#pragma once
// Symmetric compositions of the Strang step of a splittable system (see
// splitting.hpp): S(w_1 h) S(w_2 h) ... S(w_s h), with sum w_i = 1 and
// symmetric weights, raise the Strang step's order 2 to the scheme's order.
// The outer sub-flow 0 of consecutive Strang steps is merged (flow(0, a) then
// flow(0, b) is flow(0, a + b): one sub-flow is a one-parameter group), so a
// composition of s Strang steps costs s evaluations of the inner sub-flows and
// s + 1 of sub-flow 0.
//
// Schemes (weights of the Strang steps):
//  * Strang2: the Strang step itself (order 2).
//  * TripleJump4 (Yoshida 1990 / Suzuki 1990 / Creutz-Gocksch): w1 = w3 = 1/(2 - 2^(1/3)),
//    w2 = 1 - 2 w1 = -1.70: 3 stages, but a backward middle step 1.7 times h
//    and sum |w_i| = 4.4, hence a large leading error constant.
//  * Suzuki5 (Suzuki 1990 "fractal" 5-stage): w = (p, p, 1 - 4p, p, p),
//    p = 1/(4 - 4^(1/3)) = 0.4145, middle -0.658, sum |w_i| = 2.3. Its
//    leading error constant is much smaller (McLachlan, SIAM J. Sci. Comput. 16
//    (1995); Hairer-Lubich-Wanner, Geometric Numerical Integration, V.3): at equal
//    work (5 vs 3 stages) it is more accurate whenever the error-constant ratio
//    exceeds (5/3)^4 = 7.7. On the heavy top with the exact free-flow splitting we
//    measured, at equal work (Suzuki5 with step h against the triple jump with 3h/5),
//    errors 9.5x smaller (tests/sim/exact_split_test.cpp,
//    ExactSplit.Suzuki5BeatsTripleJumpAtEqualWork), i.e. 9.5^(1/4) = 1.75x less work
//    at equal error: Composition4 uses Suzuki5.
#include <array>
#include <cmath>

#include "numerics/stepper_common.hpp"

namespace epviz::numerics {

struct Strang2 {
  static constexpr int order = 2;
  static constexpr std::array<double, 1> weights() { return {1.0}; }
};

struct TripleJump4 {
  static constexpr int order = 4;
  static std::array<double, 3> weights() {
    const double w1 = 1.0 / (2.0 - std::cbrt(2.0));
    return {w1, 1.0 - 2.0 * w1, w1};
  }
};

struct Suzuki5 {
  static constexpr int order = 4;
  static std::array<double, 5> weights() {
    const double p = 1.0 / (4.0 - std::cbrt(4.0));
    return {p, p, 1.0 - 4.0 * p, p, p};
  }
};

template <class Sys, class Scheme>
requires SplittableSystem<Sys>
class SymmetricComposition : public StepperCore<Sys> {
  using StepperCore<Sys>::sys_;
  using StepperCore<Sys>::stats_;

 public:
  using System = Sys;
  using State = typename Sys::State;
  static constexpr int order = Scheme::order;
  static constexpr int n_flows = Sys::n_flows;
  static_assert(n_flows >= 2, "a composition of Strang steps needs at least two sub-flows");

  // `name`: the method's name in failure reports (a string literal).
  explicit SymmetricComposition(Sys sys, const char* name = "composition")
      : StepperCore<Sys>(std::move(sys)), name_(name) {
    const auto w = Scheme::weights();
    for (std::size_t i = 0; i < w.size(); ++i) w_[i] = w[i];
  }

  // Advances x from t to t + h. Throws IntegrationError on a non-finite result
  // or when the system's check() objects; x is then left unchanged.
  inline void step(State& x, double t, double h) {
    detail::regularize(sys_, x);
    tmp_ = x;
    constexpr int s = int(std::tuple_size_v<decltype(Scheme::weights())>);
    double pending = 0.5 * w_[0] * h;  // sub-flow 0 still to apply
    for (int k = 0; k < s; ++k) {
      const double hk = w_[k] * h;
      sys_.flow(0, pending, tmp_);
      for (int i = 1; i < n_flows - 1; ++i) sys_.flow(i, 0.5 * hk, tmp_);
      sys_.flow(n_flows - 1, hk, tmp_);
      for (int i = n_flows - 2; i >= 1; --i) sys_.flow(i, 0.5 * hk, tmp_);
      pending = 0.5 * hk + (k + 1 < s ? 0.5 * w_[k + 1] * h : 0.0);
    }
    sys_.flow(0, pending, tmp_);
    stats_.flow_evals += s * (2 * n_flows - 3) + s + 1;
    this->accept(x, tmp_, t + h, name_);
  }

  const char* name() const { return name_; }

 private:
  const char* name_;
  std::array<double, std::tuple_size_v<decltype(Scheme::weights())>> w_{};
  State tmp_ = State::Zero();
};

// The 4th-order composition of a Strang-able system's Strang step (Suzuki5 by
// default; see the comment at the top for why not the triple jump).
template <class Sys, class Scheme = Suzuki5>
class Composition4 : public SymmetricComposition<Sys, Scheme> {
 public:
  static_assert(Scheme::order == 4);
  explicit Composition4(Sys sys, const char* name = "composition4")
      : SymmetricComposition<Sys, Scheme>(std::move(sys), name) {}
};

// The Strang step as a composition (order 2), with its own name in failure reports.
template <class Sys>
class Composition2 : public SymmetricComposition<Sys, Strang2> {
 public:
  explicit Composition2(Sys sys, const char* name = "composition2")
      : SymmetricComposition<Sys, Strang2>(std::move(sys), name) {}
};

}  // namespace epviz::numerics
