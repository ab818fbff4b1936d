#pragma once
// Implicit Gauss–Legendre collocation methods, fixed step:
//
//   ImplicitMidpoint<Sys>  1 stage, order 2  ("midpoint")
//   Gauss4<Sys>            2 stages, order 4 ("gauss4")
//   Gauss6<Sys>            3 stages, order 6 ("gauss6")
//
// They are symmetric and symplectic and conserve every quadratic first
// integral of the system exactly; to keep that property in floating point the
// stage equations are solved by fixed-point iteration down to round-off, and
// the update x + h sum b_i f_i is added with compensated (Kahan) summation
// carried from step to step.
//
// The stage equations are solved for the increments Z_i = X_i - x:
//   Z_i = h sum_j a_ij f(t + c_j h, x + Z_j).
// Starting guess: when the step continues the previous one (same state object
// value, t = previous t + h), the previous collocation polynomial is
// extrapolated; otherwise the explicit Euler guess Z_i = c_i h f(t, x).
// The iteration stops when the increment vanishes or stops decreasing at
// round-off level. (Stopping earlier, e.g. once it falls below a few ulps of
// Z, leaves an iteration error that is systematic from step to step and makes
// quadratic invariants drift by ~1e-12 over 1e5 steps; at the round-off floor
// the remaining error is random.) The fixed-point iteration converges only for
// h L small (L a Lipschitz constant): for stiff problems it reports failure.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "numerics/stepper_common.hpp"

namespace epviz::numerics {

struct ImplicitOptions {
  int max_iterations = 100;  // fixed-point iterations per step
};

template <int Stages>
struct GaussTableau;

template <>
struct GaussTableau<1> {
  static constexpr const char* name = "midpoint";
  static constexpr int order = 2;
  static constexpr std::array<double, 1> c = {0.5};
  static constexpr std::array<double, 1> b = {1.0};
  static constexpr std::array<std::array<double, 1>, 1> a = {{{0.5}}};
};

template <>
struct GaussTableau<2> {
  static constexpr const char* name = "gauss4";
  static constexpr int order = 4;
  static constexpr double r = 0.2886751345948128822545743902509787;  // sqrt(3)/6
  static constexpr std::array<double, 2> c = {0.5 - r, 0.5 + r};
  static constexpr std::array<double, 2> b = {0.5, 0.5};
  static constexpr std::array<std::array<double, 2>, 2> a = {{{0.25, 0.25 - r}, {0.25 + r, 0.25}}};
};

template <>
struct GaussTableau<3> {
  static constexpr const char* name = "gauss6";
  static constexpr int order = 6;
  static constexpr double r10 = 0.3872983346207416885179265399782400;  // sqrt(15)/10
  static constexpr double r15 = 0.2581988897471611256786176933188266;  // sqrt(15)/15
  static constexpr double r24 = 0.1613743060919757035491360583242667;  // sqrt(15)/24
  static constexpr double r30 = 0.1290994448735805628393088466594133;  // sqrt(15)/30
  static constexpr std::array<double, 3> c = {0.5 - r10, 0.5, 0.5 + r10};
  static constexpr std::array<double, 3> b = {5.0 / 18.0, 4.0 / 9.0, 5.0 / 18.0};
  static constexpr std::array<std::array<double, 3>, 3> a = {{
      {5.0 / 36.0, 2.0 / 9.0 - r15, 5.0 / 36.0 - r30},
      {5.0 / 36.0 + r24, 2.0 / 9.0, 5.0 / 36.0 - r24},
      {5.0 / 36.0 + r30, 2.0 / 9.0 + r15, 5.0 / 36.0},
  }};
};

template <OdeSystem Sys, int Stages>
class GaussLegendre : public StepperCore<Sys> {
  using StepperCore<Sys>::sys_;
  using StepperCore<Sys>::stats_;
  static_assert(Stages >= 1 && Stages <= 3, "Gauss–Legendre with 1, 2 or 3 stages");
  using T = GaussTableau<Stages>;

 public:
  using System = Sys;
  using State = typename Sys::State;
  static constexpr const char* name = T::name;
  static constexpr int order = T::order;
  static constexpr int stages = Stages;

  explicit GaussLegendre(Sys sys, ImplicitOptions opts = {})
      : StepperCore<Sys>(std::move(sys)), opts_(opts) {}

  // Advances x from t to t + h. Throws IntegrationError when the stage
  // equations do not converge, on a non-finite result, or when the system's
  // check() objects; x is then left unchanged (apart from a regularize()
  // remapping at the start of the step).
  void step(State& x, double t, double h);

  const ImplicitOptions& options() const { return opts_; }
  int last_iterations() const { return last_iterations_; }

 private:
  static constexpr double eps = std::numeric_limits<double>::epsilon();

  // W(i, j) = l_j(1 + c_i r) - l_j(1), l_j the Lagrange basis on the nodes
  // {0, c_1, ..., c_s} belonging to c_j: extrapolates the increments of the
  // previous step (length h_prev) to the stages of the next (length r h_prev).
  void update_extrapolation(double r) {
    if (r == w_ratio_) return;
    std::array<double, Stages + 1> nodes{};
    for (int j = 0; j < Stages; ++j) nodes[j + 1] = T::c[j];
    auto basis = [&](int j, double theta) {  // j indexes nodes (1..s)
      double v = 1.0;
      for (int m = 0; m <= Stages; ++m)
        if (m != j) v *= (theta - nodes[m]) / (nodes[j] - nodes[m]);
      return v;
    };
    for (int i = 0; i < Stages; ++i)
      for (int j = 0; j < Stages; ++j)
        w_[i][j] = basis(j + 1, 1.0 + T::c[i] * r) - basis(j + 1, 1.0);
    w_ratio_ = r;
  }

  ImplicitOptions opts_;
  int last_iterations_ = 0;
  static std::array<State, Stages> zeros() {
    std::array<State, Stages> a;
    a.fill(State::Zero());
    return a;
  }
  std::array<State, Stages> z_ = zeros(), f_ = zeros(), znew_ = zeros();
  State tmp_ = State::Zero(), comp_ = State::Zero(), x_out_ = State::Zero();
  bool have_prev_ = false;  // z_, comp_, x_out_ describe the previous step
  double t_end_ = 0, h_prev_ = 0;
  double w_ratio_ = std::numeric_limits<double>::quiet_NaN();
  std::array<std::array<double, Stages>, Stages> w_{};
};

template <OdeSystem Sys, int Stages>
void GaussLegendre<Sys, Stages>::step(State& x, double t, double h) {
  if (detail::regularize(sys_, x)) have_prev_ = false;

  const bool continues = have_prev_ && x == x_out_ &&
                         std::abs(t - t_end_) <= 1e-6 * std::abs(h_prev_) + 8 * eps * std::abs(t);
  if (continues) {
    update_extrapolation(h / h_prev_);
    for (int i = 0; i < Stages; ++i) {
      znew_[i] = w_[i][0] * z_[0];
      for (int j = 1; j < Stages; ++j) znew_[i] += w_[i][j] * z_[j];
    }
    z_ = znew_;
  } else {
    sys_.rhs(t, x, f_[0]);
    ++stats_.rhs_evals;
    for (int i = 0; i < Stages; ++i) z_[i] = (T::c[i] * h) * f_[0];
    comp_.setZero();
  }
  have_prev_ = false;

  const double xmax = x.cwiseAbs().maxCoeff();
  double d_old = std::numeric_limits<double>::infinity();
  int growing = 0;
  bool converged = false;
  int it = 0;
  while (it < opts_.max_iterations) {
    ++it;
    for (int i = 0; i < Stages; ++i) {
      tmp_.noalias() = x + z_[i];
      sys_.rhs(t + T::c[i] * h, tmp_, f_[i]);
    }
    stats_.rhs_evals += Stages;
    ++stats_.solver_iterations;
    double d = 0, zmax = 0;
    for (int i = 0; i < Stages; ++i) {
      znew_[i] = (h * T::a[i][0]) * f_[0];
      for (int j = 1; j < Stages; ++j) znew_[i] += (h * T::a[i][j]) * f_[j];
      d = std::max(d, (znew_[i] - z_[i]).cwiseAbs().maxCoeff());
      zmax = std::max(zmax, znew_[i].cwiseAbs().maxCoeff());
    }
    z_ = znew_;
    if (!std::isfinite(d) || !std::isfinite(zmax)) break;
    if (d == 0.0) {
      converged = true;
      break;
    }
    if (d >= d_old) {
      // Stopped decreasing: converged if at round-off level, else diverging.
      if (d <= 1024 * eps * std::max(xmax, zmax)) {
        converged = true;
        break;
      }
      if (++growing >= 8) break;
    } else {
      growing = 0;
    }
    d_old = d;
  }
  last_iterations_ = it;
  if (!converged) [[unlikely]] {
    // The fixed-point iteration contracts only while h times the Lipschitz
    // constant is well below 1: with this step it does not.
    char fact[128];
    std::snprintf(fact, sizeof fact,
                  "implicit stage equations did not converge in %d iterations (step size %.3g)", it,
                  h);
    detail::throw_failure(t, name, FailureKind::solver_divergence, fact);
  }

  // x_new = x + h sum b_i f_i, with the rounding error carried to the next step.
  State delta = (h * T::b[0]) * f_[0];
  for (int i = 1; i < Stages; ++i) delta += (h * T::b[i]) * f_[i];
  delta += comp_;
  tmp_ = x + delta;
  detail::check_accepted(sys_, tmp_, t + h, name);
  comp_ = (x - tmp_) + delta;
  x = tmp_;
  x_out_ = tmp_;
  t_end_ = t + h;
  h_prev_ = h;
  have_prev_ = true;
  ++stats_.steps;
}

template <OdeSystem Sys>
using ImplicitMidpoint = GaussLegendre<Sys, 1>;
template <OdeSystem Sys>
using Gauss4 = GaussLegendre<Sys, 2>;
template <OdeSystem Sys>
using Gauss6 = GaussLegendre<Sys, 3>;

}  // namespace epviz::numerics
