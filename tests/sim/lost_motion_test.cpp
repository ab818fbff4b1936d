// A run hands out only samples that keep the motion: finite, with a relative
// drift of the energy and of |gamma|^2 within RunSpec::max_drift. The first
// output time that breaks this ends the run as a numerical failure, so that no
// front end writes or draws it.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>

#include "run_helpers.hpp"
#include "sim/drift.hpp"

namespace epviz {
namespace {

using numerics::FailureKind;

// A fast sleeping top (Omega3 = 50, tilted 5 degrees) in the Riccati
// formulation with RK4 and a step of 2: far beyond RK4's stability limit.
sim::RunSpec fast_top(double max_drift = sim::kDefaultMaxDrift) {
  auto spec =
      sim::preset_run(physics::Case::lagrange, sim::Method::rk4, sim::Formulation::riccati, 40, 20);
  const double tilt = 5.0 * std::numbers::pi / 180.0;
  spec.initial.omega = {0.0, 0.0, 50.0};
  spec.initial.gamma = {std::sin(tilt), 0.0, std::cos(tilt)};
  spec.step = 2.0;
  spec.max_drift = max_drift;
  return spec;
}

bool finite(const sim::Sample& s) { return s.omega.allFinite() && s.gamma.allFinite(); }

// The relative drifts written out here, independently of physics/invariants:
// C1 = 1/2 sum I_i Omega_i^2 + P r.gamma, measured against
// max(|C1(0)|, 1/2 sum I_i Omega_i(0)^2 + P |r| |gamma(0)|); |gamma|^2 against 1.
struct Oracle {
  const sim::RunSpec& spec;
  double energy(const Eigen::Vector3d& w, const Eigen::Vector3d& g) const {
    const auto& b = spec.body;
    double kinetic = 0.0;
    for (int i = 0; i < 3; ++i) kinetic += 0.5 * b.inertia[i] * w[i] * w[i];
    return kinetic + b.weight * (b.com[0] * g[0] + b.com[1] * g[1] + b.com[2] * g[2]);
  }
  double energy_drift(const sim::Sample& s) const {
    const auto& w0 = spec.initial.omega;
    const auto& g0 = spec.initial.gamma;
    const double e0 = energy(w0, g0);
    const double kinetic0 = energy(w0, Eigen::Vector3d::Zero());
    const double scale =
        std::max(std::abs(e0), kinetic0 + spec.body.weight * spec.body.com.norm() * g0.norm());
    return std::abs(energy(s.omega, s.gamma) - e0) / scale;
  }
  double gamma_drift(const sim::Sample& s) const {
    return std::abs(s.gamma.squaredNorm() - spec.initial.gamma.squaredNorm());
  }
  // The index of the first sample that is not finite or drifts above `limit`.
  std::optional<std::size_t> first_lost(const std::vector<sim::Sample>& samples,
                                        double limit) const {
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const auto& s = samples[i];
      if (!finite(s) || !(energy_drift(s) <= limit && gamma_drift(s) <= limit)) return i;
    }
    return std::nullopt;
  }
};

TEST(LostMotion, NoSampleHandedOutIsNonFinite) {
  const auto r = sim::simulate(fast_top());
  ASSERT_TRUE(r.failure.has_value());
  for (const auto& s : r.samples) EXPECT_TRUE(finite(s)) << "t = " << s.t;
  EXPECT_GT(r.failure->t, r.samples.back().t);
  EXPECT_EQ(r.failure->method, "rk4");
}

TEST(LostMotion, FailsAtTheFirstOutputTimeAboveTheLimit) {
  // The same run without a limit worth the name, as the oracle's data: it goes
  // on until it is no longer finite.
  const auto spec = fast_top();
  const auto unlimited = sim::simulate(fast_top(std::numeric_limits<double>::max()));
  const Oracle oracle{spec};
  const auto lost = oracle.first_lost(unlimited.samples, sim::kDefaultMaxDrift);
  ASSERT_TRUE(lost.has_value()) << "the oracle sees no lost motion";
  ASSERT_GT(*lost, 0u);
  const double t_lost = unlimited.samples[*lost].t;
  // It is lost while still finite: large drift first, NaN or Inf later.
  ASSERT_TRUE(finite(unlimited.samples[*lost]));
  ASSERT_GT(oracle.energy_drift(unlimited.samples[*lost]), 1.0);

  const auto r = sim::simulate(spec);
  ASSERT_TRUE(r.failure.has_value());
  EXPECT_EQ(r.failure->kind, FailureKind::lost_motion) << r.failure->message();
  EXPECT_DOUBLE_EQ(r.failure->t, t_lost);
  ASSERT_EQ(r.samples.size(), *lost);  // every sample before it, none after
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    EXPECT_EQ(r.samples[i].t, unlimited.samples[i].t);
    EXPECT_LE(oracle.energy_drift(r.samples[i]), 1.0);
  }
  // The fact names the drift and the limit, and no option of any front end.
  EXPECT_NE(r.failure->detail.find("lost the motion"), std::string::npos) << r.failure->detail;
  EXPECT_NE(r.failure->detail.find("energy drift"), std::string::npos) << r.failure->detail;
  EXPECT_NE(r.failure->detail.find("limit 1"), std::string::npos) << r.failure->detail;
  EXPECT_EQ(r.failure->detail.find("--"), std::string::npos) << r.failure->detail;
}

TEST(LostMotion, AHighLimitLetsTheRunGoOnUntilItIsNotFinite) {
  const auto limited = sim::simulate(fast_top());
  const auto r = sim::simulate(fast_top(1e300));
  ASSERT_TRUE(limited.failure.has_value());
  ASSERT_TRUE(r.failure.has_value());
  EXPECT_EQ(r.failure->kind, FailureKind::non_finite) << r.failure->message();
  EXPECT_GT(r.failure->t, limited.failure->t);
  for (const auto& s : r.samples) EXPECT_TRUE(finite(s)) << "t = " << s.t;
}

TEST(LostMotion, TheLimitIsTheRunsOwn) {
  // Each limit cuts the same run at the oracle's first sample above it.
  const auto unlimited = sim::simulate(fast_top(std::numeric_limits<double>::max()));
  const Oracle oracle{fast_top()};
  for (double limit : {1e-3, 0.1, 10.0, 1e6}) {
    const auto lost = oracle.first_lost(unlimited.samples, limit);
    ASSERT_TRUE(lost.has_value()) << limit;
    const auto r = sim::simulate(fast_top(limit));
    ASSERT_TRUE(r.failure.has_value()) << limit;
    EXPECT_EQ(r.samples.size(), *lost) << limit;
    EXPECT_DOUBLE_EQ(r.failure->t, unlimited.samples[*lost].t) << limit;
  }
}

TEST(LostMotion, AnAccurateRunIsNotStopped) {
  auto spec = fast_top();
  spec.method = sim::Method::dop853;
  spec.tol = 1e-10;
  const auto r = sim::simulate(spec);
  EXPECT_FALSE(r.failure) << r.failure->message();
  EXPECT_EQ(r.samples.size(), std::size_t(spec.samples) + 1);
}

// The check itself, on samples made by hand: a body with its centre of mass
// at the fixed point, so that the energy depends on Omega alone.
struct HandMade : ::testing::Test {
  physics::Body body;
  physics::InitialState initial;
  HandMade() {
    body.inertia = {1.0, 2.0, 3.0};
    body.com = {0.0, 0.0, 0.0};
    body.weight = 1.0;
    initial.omega = {1.0, 0.0, 0.0};  // energy 1/2
    initial.gamma = {0.0, 0.0, 1.0};
  }
  sim::Sample sample(Eigen::Vector3d w, Eigen::Vector3d g) const {
    sim::Sample s;
    s.t = 1.5;
    s.omega = w;
    s.gamma = g;
    return s;
  }
};

TEST_F(HandMade, EnergyAndGammaDriftsAreEachLimited) {
  const sim::MotionCheck check(body, initial, 1.0);
  const Eigen::Vector3d up(0, 0, 1);
  // Energy w^2 / 2 against 1/2: drift w^2 - 1, 0.95 at w^2 = 1.95, 1.05 at 2.05.
  EXPECT_FALSE(check.failure(sample({std::sqrt(1.95), 0, 0}, up), "rk4"));
  const auto energy = check.failure(sample({std::sqrt(2.05), 0, 0}, up), "rk4");
  ASSERT_TRUE(energy.has_value());
  EXPECT_EQ(energy->kind, FailureKind::lost_motion);
  EXPECT_EQ(energy->t, 1.5);
  EXPECT_EQ(energy->method, "rk4");
  EXPECT_NE(energy->detail.find("energy drift 1.05"), std::string::npos) << energy->detail;
  // |gamma|^2 = 1.96 (drift 0.96) keeps the motion, 2.1025 (drift 1.1025) does not.
  const Eigen::Vector3d w0 = initial.omega;
  EXPECT_FALSE(check.failure(sample(w0, {0, 0, 1.4}), "rk4"));
  const auto gamma = check.failure(sample(w0, {0, 0, 1.45}), "rk4");
  ASSERT_TRUE(gamma.has_value());
  EXPECT_EQ(gamma->kind, FailureKind::lost_motion);
  EXPECT_NE(gamma->detail.find("|gamma|^2 drift 1.1"), std::string::npos) << gamma->detail;
}

TEST_F(HandMade, NonFiniteSamplesFailAsNonFinite) {
  const sim::MotionCheck check(body, initial, 1e300);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  // The last two are finite, but their energy or |gamma|^2 overflows.
  for (const auto& s : {sample({nan, 0, 0}, {0, 0, 1}), sample({1, 0, 0}, {0, -nan, 1}),
                        sample({inf, 0, 0}, {0, 0, 1}), sample({1e200, 0, 0}, {0, 0, 1}),
                        sample({1, 0, 0}, {0, 0, 1e200})}) {
    const auto f = check.failure(s, "dop853");
    ASSERT_TRUE(f.has_value());
    EXPECT_EQ(f->kind, FailureKind::non_finite);
  }
  auto turned = sample({1, 0, 0}, {0, 0, 1});
  turned.attitude = Eigen::Quaterniond(nan, 0, 0, 1);
  ASSERT_TRUE(check.failure(turned, "dop853").has_value());
  turned.attitude = Eigen::Quaterniond::Identity();
  EXPECT_FALSE(check.failure(turned, "dop853").has_value());
}

}  // namespace
}  // namespace epviz
