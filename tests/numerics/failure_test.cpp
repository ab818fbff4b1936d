// Failure detection: every stepper throws IntegrationError with a usable
// Failure (its kind and a plain fact) instead of returning a state it cannot
// trust; regularize() and check() hooks are honoured.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "numerics/embedded_rk.hpp"
#include "numerics/gauss_legendre.hpp"
#include "numerics/rk4.hpp"
#include "numerics/splitting.hpp"
#include "provoked_failures.hpp"
#include "test_systems.hpp"

namespace epviz::numerics {
namespace {

using testing::ExpBlowUp;
using testing::failure_thrown_by;
using testing::Linear1;
using testing::Provoked;
using testing::run_until_failure;
using testing::step_until_failure;

bool contains(const std::string& s, const std::string& what) {
  return s.find(what) != std::string::npos;
}

template <template <class> class Method>
void expect_blow_up_detected(const char* name, FailureKind kind) {
  const auto [s, f] = testing::provoke_step_underflow<Method>();
  EXPECT_EQ(f.method, name);
  // The numerical solution has its own pole, within the accumulated error of 1.
  EXPECT_NEAR(f.t, 1.0, 1e-6);
  EXPECT_EQ(f.kind, kind) << f.message();
  EXPECT_FALSE(f.detail.empty());
  // The last accepted state is still the (huge but finite) solution.
  EXPECT_TRUE(s.state().allFinite());
  EXPECT_GT(s.state()[0], 1e8);
  EXPECT_LE(s.t(), f.t);
}

TEST(Failure, AdaptiveMethodsStopAtABlowUp) {
  expect_blow_up_detected<Dop853>("dop853", FailureKind::step_underflow);
  expect_blow_up_detected<Dopri5>("dopri5", FailureKind::step_underflow);
}

TEST(Failure, StepSizeUnderflowIsNamed) {
  const Failure f = testing::provoke_step_underflow().failure;
  EXPECT_EQ(f.kind, FailureKind::step_underflow);
  EXPECT_TRUE(contains(f.detail, "below the round-off limit")) << f.detail;
  EXPECT_TRUE(contains(f.message(), "dop853 failed at t = ")) << f.message();
  EXPECT_TRUE(contains(f.message(), f.detail)) << f.message();
}

TEST(Failure, Rk4HugeStepOnABlowUpIsNonFinite) {
  const auto [s, x, f] = step_until_failure(Rk4<ExpBlowUp>({}), 1.0, 100.0);
  EXPECT_EQ(f.method, "rk4");
  EXPECT_EQ(f.kind, FailureKind::non_finite);
  EXPECT_TRUE(contains(f.detail, "not finite")) << f.detail;
  EXPECT_EQ(f.t, 100.0);
  EXPECT_EQ(x[0], 1.0);  // the state is left as it was
}

TEST(Failure, FixedStepDop853NonFinite) {
  const Failure f = step_until_failure(Dop853<ExpBlowUp>({}), 1.0, 100.0).failure;
  EXPECT_EQ(f.method, "dop853");
  EXPECT_EQ(f.kind, FailureKind::non_finite);
}

template <template <class> class Method>
void expect_no_convergence(const char* name) {
  auto [s, x, f] = step_until_failure(Method<Linear1>(Linear1{-1000.0}), 1.0, 0.1);
  EXPECT_EQ(f.method, name);
  EXPECT_EQ(f.kind, FailureKind::solver_divergence);
  EXPECT_TRUE(contains(f.detail, "did not converge")) << f.detail;
  EXPECT_EQ(x[0], 1.0);
  // With a small enough step the same stepper works (h lambda = -0.1).
  s.step(x, 0.0, 1e-4);
  EXPECT_NEAR(x[0], std::exp(-0.1), 1e-4);
}

TEST(Failure, GaussTooLargeStepOnStiffProblemDoesNotConverge) {
  expect_no_convergence<ImplicitMidpoint>("midpoint");
  expect_no_convergence<Gauss4>("gauss4");
  expect_no_convergence<Gauss6>("gauss6");
}

TEST(Failure, GaussIterationLimitIsAnOption) {
  // Converging, but slowly (h |lambda| a = 0.45): 3 iterations are not enough.
  auto [s, x, f] =
      step_until_failure(ImplicitMidpoint<Linear1>(Linear1{-9.0}, ImplicitOptions{3}), 1.0, 0.1);
  EXPECT_EQ(f.kind, FailureKind::solver_divergence);
  EXPECT_TRUE(contains(f.detail, "did not converge in 3 iterations")) << f.detail;
  EXPECT_EQ(s.stats().solver_iterations, 3);
  ImplicitMidpoint<Linear1> ok(Linear1{-9.0});
  ok.step(x, 0.0, 0.1);
  EXPECT_NEAR(x[0], (1 - 0.45) / (1 + 0.45), 1e-15);  // the midpoint rule's own value
}

// y' = 1, with an issue reported beyond y = 1.55 (think: Riccati pole).
struct Checked {
  static constexpr int dim = 1;
  static constexpr int n_flows = 1;
  using State = Vec<1>;
  void rhs(double, const State&, State& dx) const { dx[0] = 1.0; }
  void flow(int, double h, State& x) const { x[0] += h; }
  std::optional<Issue> check(const State& x) const {
    if (x[0] > 1.55) return Issue{FailureKind::chart_pole, "near the pole"};
    return std::nullopt;
  }
};

template <class Stepper>
void expect_issue_reported_fixed(Stepper stepper) {
  const auto [s, x, f] = step_until_failure(std::move(stepper), 0.0, 0.1, 100);
  EXPECT_EQ(f.method, Stepper::name);
  EXPECT_EQ(f.kind, FailureKind::chart_pole);
  EXPECT_EQ(f.detail, "near the pole");
  EXPECT_NEAR(f.t, 1.6, 1e-12);
  EXPECT_NEAR(x[0], 1.5, 1e-12);  // the last trusted state
}

TEST(Failure, SystemCheckIssueIsReported) {
  expect_issue_reported_fixed(Rk4<Checked>({}));
  expect_issue_reported_fixed(ImplicitMidpoint<Checked>({}));
  expect_issue_reported_fixed(Gauss4<Checked>({}));
  expect_issue_reported_fixed(Gauss6<Checked>({}));
  expect_issue_reported_fixed(StrangSplitting<Checked>({}));
  expect_issue_reported_fixed(Dopri5<Checked>({}));  // fixed-step mode

  AdaptiveOptions o;
  o.h_max = 0.1;
  Dop853<Checked> s({}, o);
  s.init(0.0, Vec<1>(0.0));
  const Failure f = failure_thrown_by([&] {
    while (s.t() < 10) s.step();
  });
  EXPECT_EQ(f.method, "dop853");
  EXPECT_EQ(f.kind, FailureKind::chart_pole);
  EXPECT_EQ(f.detail, "near the pole");
  EXPECT_GT(f.t, 1.5);
  EXPECT_LE(s.state()[0], 1.55);
  EXPECT_GT(s.state()[0], 1.4);
}

// Non-finite everywhere but at the start: every trial step fails.
struct NanAfterStart {
  static constexpr int dim = 1;
  using State = Vec<1>;
  void rhs(double t, const State&, State& dx) const {
    dx[0] = t == 0.0 ? 1.0 : std::numeric_limits<double>::quiet_NaN();
  }
};

// Five rejections allowed in a row: the first step fails.
Provoked<Dopri5<NanAfterStart>> provoke_nan_rejections() {
  AdaptiveOptions o;
  o.max_consecutive_rejects = 5;
  return run_until_failure(Dopri5<NanAfterStart>({}, o), 0.0, 1.0);
}

TEST(Failure, TooManyConsecutiveRejections) {
  const auto [s, f] = provoke_nan_rejections();
  EXPECT_EQ(f.method, "dopri5");
  // Every trial was NaN: the solution itself is not finite, whatever the step.
  EXPECT_EQ(f.kind, FailureKind::non_finite);
  EXPECT_TRUE(contains(f.detail, "not finite")) << f.detail;
  EXPECT_EQ(s.stats().rejected_steps, 6);
  EXPECT_EQ(s.stats().steps, 0);
  EXPECT_EQ(f.t, 0.0);
}

// Smooth, but the error test always fails: y' = 1e6 y (atol tiny) with h_min-free control.
TEST(Failure, TooManyConsecutiveRejectionsFinite) {
  const auto [s, f] = testing::provoke_rejections();
  EXPECT_EQ(f.kind, FailureKind::rejections);
  EXPECT_TRUE(contains(f.detail, "3 consecutive rejected steps")) << f.detail;
  EXPECT_EQ(s.stats().rejected_steps, 3);
}

TEST(Failure, MaxStepsExceeded) {
  const auto [s, f] = testing::provoke_step_budget();
  EXPECT_EQ(f.kind, FailureKind::step_budget);
  EXPECT_TRUE(contains(f.detail, "step budget of 10 steps exhausted")) << f.detail;
  EXPECT_EQ(s.stats().steps, 10);
  EXPECT_NEAR(f.t, 0.1, 1e-12);
}

Provoked<Dop853<Linear1>> provoke_infinite_start() {
  return run_until_failure(Dop853<Linear1>(Linear1{-1.0}), std::numeric_limits<double>::infinity(),
                           1.0);
}

TEST(Failure, NonFiniteInitialState) {
  const Failure f = provoke_infinite_start().failure;
  EXPECT_EQ(f.kind, FailureKind::non_finite);
  EXPECT_TRUE(contains(f.detail, "not finite")) << f.detail;
}

// Splitting with a sub-flow that overflows.
struct Overflowing {
  static constexpr int dim = 1;
  static constexpr int n_flows = 2;
  using State = Vec<1>;
  void flow(int i, double h, State& x) const { x[0] = i == 0 ? x[0] * std::exp(1000 * h) : x[0]; }
};

TEST(Failure, SplittingNonFinite) {
  const Failure f = step_until_failure(StrangSplitting<Overflowing>({}), 1.0, 1.0).failure;
  EXPECT_EQ(f.method, "splitting");
  EXPECT_EQ(f.kind, FailureKind::non_finite);
}

// ---- Failures are data: a kind with a stable name, and a fact without advice.

TEST(FailureKind, NamesAreDistinctSnakeCase) {
  std::vector<std::string> seen;
  for (FailureKind k : kFailureKinds) {
    const std::string n(name(k));
    ASSERT_FALSE(n.empty());
    for (char c : n) EXPECT_TRUE((c >= 'a' && c <= 'z') || c == '_') << n;
    for (const auto& other : seen) EXPECT_NE(n, other);
    seen.push_back(n);
  }
  // The list holds every enumerator once (they are numbered from 0 in order).
  for (std::size_t i = 0; i < kFailureKinds.size(); ++i)
    EXPECT_EQ(static_cast<std::size_t>(kFailureKinds[i]), i);
  EXPECT_EQ(name(FailureKind::step_underflow), "step_underflow");
  EXPECT_EQ(name(FailureKind::chart_pole), "chart_pole");
}

// Every failure a stepper can raise, provoked on the small test systems.
std::vector<Failure> provoked_failures() {
  std::vector<Failure> all;
  // non_finite: a fixed step far too large for an exponential blow-up, NaN
  // derivatives everywhere but at the start (adaptive), an infinite initial state
  all.push_back(step_until_failure(Rk4<ExpBlowUp>({}), 1.0, 100.0).failure);
  all.push_back(provoke_nan_rejections().failure);
  all.push_back(provoke_infinite_start().failure);
  // step_underflow, step_budget, rejections
  for (const Failure& f : testing::step_control_failures()) all.push_back(f);
  // solver_divergence
  all.push_back(step_until_failure(Gauss4<Linear1>(Linear1{-1000.0}), 1.0, 0.1).failure);
  // a system's check(): the stepper passes the issue's kind through
  all.push_back(step_until_failure(Rk4<Checked>({}), 0.0, 0.1, 100).failure);
  return all;
}

TEST(Failure, TextNamesNoCommandLineFlag) {
  std::vector<FailureKind> kinds;
  for (const Failure& f : provoked_failures()) {
    kinds.push_back(f.kind);
    EXPECT_FALSE(f.detail.empty()) << name(f.kind);
    EXPECT_FALSE(contains(f.detail, "--")) << f.detail;
    EXPECT_FALSE(contains(f.message(), "--")) << f.message();
    EXPECT_FALSE(contains(f.message(), ";")) << "no advice appended here: " << f.message();
  }
  // Every kind a stepper raises was provoked. lost_motion is not raised by a
  // stepper (a finite solution far from the truth is a study's verdict).
  for (FailureKind k : kFailureKinds) {
    if (k == FailureKind::lost_motion) continue;
    EXPECT_NE(std::find(kinds.begin(), kinds.end(), k), kinds.end()) << name(k);
  }
}

// ---- regularize(): called at the start of every step; a remap drops FSAL.

// y' = y, kept in [1, 2) by halving: the system remembers how often it halved,
// so the true solution is y * 2^halvings = exp(t). A stepper that kept the
// derivative cached from before a remap would use one twice too large.
struct Halving {
  static constexpr int dim = 1;
  static constexpr int n_flows = 1;
  using State = Vec<1>;
  mutable long rhs_calls = 0;
  long regularize_calls = 0;
  int halvings = 0;
  void rhs(double, const State& x, State& dx) const {
    ++rhs_calls;
    dx[0] = x[0];
  }
  void flow(int, double h, State& x) const { x[0] *= std::exp(h); }
  bool regularize(State& x) {
    ++regularize_calls;
    if (x[0] < 2.0) return false;
    x[0] *= 0.5;
    ++halvings;
    return true;
  }
  double unscaled(const State& x) const { return std::ldexp(x[0], halvings); }
};

template <template <class> class Method>
void expect_fsal_dropped_on_remap() {
  AdaptiveOptions o;
  o.rtol = o.atol = 1e-11;
  Method<Halving> s({}, o);
  s.init(0.0, Vec<1>(1.0));
  long calls = 0;
  while (s.t() < 5.0) {
    s.step();
    ++calls;
  }
  const Halving& sys = s.system();
  EXPECT_EQ(sys.regularize_calls, calls);
  EXPECT_EQ(sys.halvings, 7);  // exp(5) = 148.4 = 1.16 * 2^7
  // The dense output of the last step is in the chart of that step.
  EXPECT_NEAR(sys.unscaled(s.dense(5.0)) / std::exp(5.0), 1.0, 1e-9);
  // Each remap costs one extra evaluation of f(t, x) (FSAL dropped).
  const Stats& st = s.stats();
  const long per_attempt = std::string(Method<Halving>::name) == "dop853" ? 11 : 6;
  const long fsal_on_accept = std::string(Method<Halving>::name) == "dop853" ? st.steps : 0;
  const long dense_extra = std::string(Method<Halving>::name) == "dop853" ? 3 : 0;
  EXPECT_EQ(st.rhs_evals, 2 + per_attempt * (st.steps + st.rejected_steps) + fsal_on_accept +
                              sys.halvings + dense_extra);
  EXPECT_EQ(st.rhs_evals, sys.rhs_calls);
}

TEST(Regularize, RemapDropsFsalDerivative) {
  expect_fsal_dropped_on_remap<Dop853>();
  expect_fsal_dropped_on_remap<Dopri5>();
}

template <class Stepper>
void expect_fixed_step_regularized(Stepper s, double tol) {
  Vec<1> x(1.0);
  const int n = 500;
  const double h = 5.0 / n;
  for (int i = 0; i < n; ++i) s.step(x, i * h, h);
  EXPECT_EQ(s.system().regularize_calls, n);
  EXPECT_EQ(s.system().halvings, 7);
  EXPECT_NEAR(s.system().unscaled(x) / std::exp(5.0), 1.0, tol) << Stepper::name;
}

TEST(Regularize, FixedStepMethodsCallItEveryStep) {
  expect_fixed_step_regularized(Rk4<Halving>({}), 1e-9);
  expect_fixed_step_regularized(ImplicitMidpoint<Halving>({}), 1e-4);
  expect_fixed_step_regularized(Gauss4<Halving>({}), 1e-10);
  expect_fixed_step_regularized(Gauss6<Halving>({}), 1e-12);
  expect_fixed_step_regularized(StrangSplitting<Halving>({}), 1e-12);
  expect_fixed_step_regularized(Dop853<Halving>({}), 1e-12);
}

}  // namespace
}  // namespace epviz::numerics
