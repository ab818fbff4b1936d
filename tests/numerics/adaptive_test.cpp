// Adaptive embedded RK methods: dense output against closed forms, the
// achieved error as a function of the tolerance, step rejection, exact work
// counters, FSAL, step-size limits.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "numerics/embedded_rk.hpp"
#include "test_systems.hpp"

namespace epviz::numerics {
namespace {

using testing::DecayingRotation;
using testing::Kepler;
using testing::observed_orders;

constexpr double kTwoPi = 6.283185307179586;

// Max error of the dense output at interior points of ONE step of size h from
// the exact initial value: the local error of the interpolant, O(h^(q+1)) for
// a continuous extension of order q (while the step end is O(h^(p+1))).
template <template <class> class Method, class Sys, class Exact>
double one_step_dense_error(const Sys& sys, Exact exact, double t0, double h) {
  AdaptiveOptions o;
  o.rtol = o.atol = 1.0;  // accept the step whatever its error
  o.h_init = h;
  o.h_max = h;
  Method<Sys> s(sys, o);
  s.init(t0, exact(t0));
  s.step();
  EXPECT_EQ(s.h_last(), h);
  double err = 0;
  for (double theta : {0.1, 0.25, 0.4, 0.55, 0.7, 0.85})
    err = std::max(err, (s.dense(t0 + theta * h) - exact(t0 + theta * h)).cwiseAbs().maxCoeff());
  // The interpolant passes through both ends of the step (up to round-off).
  EXPECT_LT((s.dense(t0 + h) - s.state()).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_EQ(s.dense(t0), exact(t0));
  return err;
}

template <template <class> class Method, class Sys, class Exact>
void expect_dense_order(const Sys& sys, Exact exact, double t0, double h0, int halvings) {
  std::vector<double> errors;
  double h = h0;
  for (int i = 0; i <= halvings; ++i, h /= 2)
    errors.push_back(one_step_dense_error<Method>(sys, exact, t0, h));
  const auto p = observed_orders(errors);
  const int expected = Method<Sys>::dense_order + 1;
  for (std::size_t i = 0; i < p.size(); ++i)
    EXPECT_NEAR(p[i], expected, 0.2)
        << Method<Sys>::name << " local dense error " << errors[i] << " -> " << errors[i + 1];
}

TEST(DenseOutput, Dopri5InterpolantHasOrder4) {
  const Kepler k{0.5};
  expect_dense_order<Dopri5>(
      k, [&](double t) { return k.exact(t); }, 3.0, 0.4, 3);
  expect_dense_order<Dopri5>(DecayingRotation{}, DecayingRotation::exact, 0.0, 0.2, 3);
}

TEST(DenseOutput, Dop853InterpolantHasOrder7) {
  const Kepler k{0.5};
  expect_dense_order<Dop853>(
      k, [&](double t) { return k.exact(t); }, 3.0, 0.8, 2);
  expect_dense_order<Dop853>(DecayingRotation{}, DecayingRotation::exact, 0.0, 0.8, 3);
}

// At a tight tolerance the dense output follows the closed form everywhere.
template <template <class> class Method>
double dense_error_over_orbit(double tol) {
  const Kepler k{0.5};
  AdaptiveOptions o;
  o.rtol = o.atol = tol;
  Method<Kepler> s(k, o);
  s.init(0.0, k.initial());
  double err = 0;
  for (int i = 1; i <= 997; ++i) {
    const double t = kTwoPi * i / 997.0;
    while (s.t() < t) s.step();
    err = std::max(err, (s.dense(t) - k.exact(t)).cwiseAbs().maxCoeff());
  }
  return err;
}

TEST(DenseOutput, MatchesClosedFormAtTightTolerance) {
  // Global errors over an eccentric orbit exceed the (local) tolerance by a
  // factor of order 100 at most.
  EXPECT_LT(dense_error_over_orbit<Dop853>(1e-11), 300 * 1e-11);
  EXPECT_LT(dense_error_over_orbit<Dopri5>(1e-10), 300 * 1e-10);
}

TEST(DenseOutput, BeforeAnyStepOnlyTheInitialPoint) {
  Dopri5<DecayingRotation> s({});
  s.init(0.0, DecayingRotation::exact(0.0));
  EXPECT_EQ(s.dense(0.0), DecayingRotation::exact(0.0));
  EXPECT_THROW(s.dense(0.1), std::logic_error);
}

// Global error at the end of one Kepler orbit for a tolerance.
template <template <class> class Method>
double global_error(double tol, long* steps = nullptr) {
  const Kepler k{0.5};
  AdaptiveOptions o;
  o.rtol = o.atol = tol;
  Method<Kepler> s(k, o);
  s.init(0.0, k.initial());
  while (s.t() < kTwoPi) s.step();
  if (steps) *steps = s.stats().steps;
  return (s.dense(kTwoPi) - k.exact(kTwoPi)).cwiseAbs().maxCoeff();
}

// Tighter tolerance, smaller error, roughly in proportion: the least-squares
// slope of log(error) against log(tol) is close to 1, and the error stays
// within a modest factor of the tolerance.
template <template <class> class Method>
void expect_tolerance_proportionality(double tol_hi, double tol_lo) {
  std::vector<double> lt, le;
  long prev_steps = 0;
  for (double tol = tol_hi; tol >= tol_lo * 0.99; tol /= 10) {
    long steps = 0;
    const double e = global_error<Method>(tol, &steps);
    EXPECT_LT(e, 300 * tol) << Method<Kepler>::name << " tol " << tol;
    EXPECT_GT(steps, prev_steps) << "tighter tolerance must take more steps";
    prev_steps = steps;
    if (!le.empty()) {
      EXPECT_LT(e, std::exp(le.back())) << "tol " << tol;
    }
    lt.push_back(std::log(tol));
    le.push_back(std::log(e));
  }
  const double n = double(lt.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < lt.size(); ++i) {
    sx += lt[i];
    sy += le[i];
    sxx += lt[i] * lt[i];
    sxy += lt[i] * le[i];
  }
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  EXPECT_NEAR(slope, 1.0, 0.25) << Method<Kepler>::name;
}

TEST(AdaptiveControl, Dopri5ErrorScalesWithTolerance) {
  expect_tolerance_proportionality<Dopri5>(1e-4, 1e-10);
}

TEST(AdaptiveControl, Dop853ErrorScalesWithTolerance) {
  expect_tolerance_proportionality<Dop853>(1e-5, 1e-12);
}

// Counts right-hand-side calls (the counter lives in the system the stepper owns).
template <class Base>
struct Counted : Base {
  mutable long calls = 0;
  void rhs(double t, const typename Base::State& x, typename Base::State& dx) const {
    ++calls;
    Base::rhs(t, x, dx);
  }
};

// y' = 0 before t = 1, then y' = 100: a sudden change of slope.
struct Kink {
  static constexpr int dim = 1;
  using State = Vec<1>;
  void rhs(double t, const State&, State& dx) const {
    dx[0] = t < 1.0 ? 0.0 : 100.0 * (t - 1.0) * (t - 1.0) + 100.0;
  }
  static double exact(double t) {
    const double s = std::max(t - 1.0, 0.0);
    return 100.0 * s + 100.0 / 3.0 * s * s * s;
  }
};

TEST(AdaptiveControl, RejectsStepsAtASuddenChangeAndCountsExactly) {
  AdaptiveOptions o;
  o.rtol = o.atol = 1e-9;
  {
    Dopri5<Counted<Kink>> s({}, o);
    s.init(0.0, Vec<1>(0.0));
    while (s.t() < 2.0) s.step();
    const Stats& st = s.stats();
    EXPECT_GT(st.rejected_steps, 0);
    // FSAL: 6 evaluations per attempt, plus f(t0) and one for the initial step size.
    EXPECT_EQ(st.rhs_evals, 2 + 6 * (st.steps + st.rejected_steps));
    EXPECT_EQ(st.rhs_evals, s.system().calls);
    EXPECT_NEAR(s.dense(2.0)[0], Kink::exact(2.0), 1e-5);
    EXPECT_EQ(st.solver_iterations, 0);
  }
  {
    Dop853<Counted<Kink>> s({}, o);
    s.init(0.0, Vec<1>(0.0));
    while (s.t() < 2.0) s.step();
    const Stats& st = s.stats();
    EXPECT_GT(st.rejected_steps, 0);
    // 11 new stages per attempt, f(t + h, x_new) once per accepted step (FSAL).
    EXPECT_EQ(st.rhs_evals, 2 + 11 * (st.steps + st.rejected_steps) + st.steps);
    EXPECT_EQ(st.rhs_evals, s.system().calls);
    const long before = st.rhs_evals;
    EXPECT_NEAR(s.dense(2.0)[0], Kink::exact(2.0), 1e-5);
    EXPECT_EQ(s.stats().rhs_evals, before + 3);  // the 3 extra dense stages, once per step
    s.dense(1.99);
    EXPECT_EQ(s.stats().rhs_evals, before + 3);
    EXPECT_EQ(s.stats().rhs_evals, s.system().calls);
  }
}

// On a problem whose difficulty varies slowly the controller rarely rejects.
// (On an eccentric orbit, the standard controller of DOP853 — Hairer's
// default, beta = 0 — rejects about one step in three while the steps shrink
// towards periapsis; the PI controller of dopri5 does not.)
template <template <class> class Method>
void expect_few_rejections(double e, double max_fraction) {
  const Kepler k{e};
  AdaptiveOptions o;
  o.rtol = o.atol = 1e-10;
  Method<Kepler> s(k, o);
  s.init(0.0, k.initial());
  while (s.t() < 10 * kTwoPi) s.step();
  EXPECT_LE(s.stats().rejected_steps, max_fraction * s.stats().steps)
      << Method<Kepler>::name << " e = " << e << ", " << s.stats().steps << " steps";
  EXPECT_GT(s.stats().steps, 50);
}

TEST(AdaptiveControl, SmoothProblemNeedsFewRejections) {
  expect_few_rejections<Dop853>(0.0, 0.02);
  expect_few_rejections<Dopri5>(0.0, 0.02);
  expect_few_rejections<Dopri5>(0.5, 0.05);
  expect_few_rejections<Dop853>(0.5, 0.5);
}

TEST(AdaptiveControl, RespectsInitialAndMaximumStep) {
  const Kepler k{0.5};
  AdaptiveOptions o;
  o.rtol = o.atol = 1e-6;
  o.h_init = 1e-3;
  o.h_max = 0.05;
  Dopri5<Kepler> s(k, o);
  s.init(0.0, k.initial());
  s.step();
  EXPECT_EQ(s.h_last(), 1e-3);
  EXPECT_EQ(s.t(), 1e-3);
  EXPECT_EQ(s.t_prev(), 0.0);
  while (s.t() < 3.0) {
    s.step();
    EXPECT_LE(s.h_last(), 0.05);
    EXPECT_NEAR(s.t() - s.t_prev(), s.h_last(), 1e-15);
  }
  EXPECT_GT(s.stats().steps, 60);  // at least 3 / 0.05
}

TEST(AdaptiveControl, AutomaticInitialStepIsReasonable) {
  const Kepler k{0.5};
  for (double tol : {1e-4, 1e-8, 1e-12}) {
    AdaptiveOptions o;
    o.rtol = o.atol = tol;
    Dop853<Kepler> s(k, o);
    s.init(0.0, k.initial());
    s.step();
    EXPECT_GT(s.h_last(), 1e-6) << tol;
    EXPECT_LT(s.h_last(), 1.0) << tol;
    EXPECT_EQ(s.stats().rejected_steps, 0) << tol;
  }
}

TEST(AdaptiveControl, InitResetsTheIntegration) {
  const Kepler k{0.5};
  Dopri5<Kepler> s(k, {});
  s.init(0.0, k.initial());
  for (int i = 0; i < 10; ++i) s.step();
  const auto x10 = s.state();
  const double t10 = s.t();
  s.init(0.0, k.initial());
  EXPECT_EQ(s.stats().steps, 0);
  EXPECT_EQ(s.t(), 0.0);
  for (int i = 0; i < 10; ++i) s.step();
  EXPECT_EQ(s.state(), x10);  // deterministic restart
  EXPECT_EQ(s.t(), t10);
}

TEST(AdaptiveControl, InvalidOptionsAreRejected) {
  AdaptiveOptions o;
  o.rtol = o.atol = 0;
  EXPECT_THROW((Dopri5<Kepler>({}, o)), std::invalid_argument);
  o = {};
  o.h_max = 0;
  EXPECT_THROW((Dop853<Kepler>({}, o)), std::invalid_argument);
  Dopri5<Kepler> s({}, {});
  EXPECT_THROW(s.step(), std::logic_error);
}

}  // namespace
}  // namespace epviz::numerics
