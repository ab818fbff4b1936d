// The exact free rigid body flow (physics/free_rigid_body_flow.hpp) against a
// tiny-step Gauss6 integration of the torque-free direct system.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "helpers.hpp"
#include "numerics/gauss_legendre.hpp"
#include "physics/direct.hpp"
#include "physics/free_rigid_body_flow.hpp"

namespace epviz::physics {
namespace {

using State = DirectSystem::State;
using Path = FreeRigidBodyFlow::Path;

// Gauss6 of the torque-free system with |Omega| dt <= ~4e-3 (error ~1e-15 per unit time).
State reference(const Vector3d& inertia, const Vector3d& w, const Vector3d& g, double h) {
  numerics::Gauss6<DirectSystem> s(DirectSystem(Body{inertia, Vector3d::Zero(), 0.0}));
  State x;
  x << w, g;
  const double wmax = inertia.cwiseProduct(w).norm() / inertia.minCoeff();
  const long n = std::max(1L, long(std::ceil(std::abs(h) * wmax / 4e-3)));
  for (long i = 0; i < n; ++i) s.step(x, double(i) * h / n, h / double(n));
  return x;
}

struct Out {
  Vector3d w, g;
  Path path;
};
Out flow(const Vector3d& inertia, Vector3d w, Vector3d g, double h) {
  const Path p = FreeRigidBodyFlow(inertia).advance(h, w, g);
  return {w, g, p};
}

// M^2 - 2 E I_mid relative to M^2 (> 0: rotation about the axis of the largest moment).
double side(const Vector3d& I, const Vector3d& w) {
  std::array<double, 3> s{I[0], I[1], I[2]};
  std::sort(s.begin(), s.end());
  const double m2 = I.cwiseProduct(w).squaredNorm();
  return (m2 - I.cwiseProduct(w).dot(w) * s[1]) / m2;
}

void expect_matches_reference(const Vector3d& I, const Vector3d& w, const Vector3d& g, double h,
                              double tol, Path expected) {
  const Out o = flow(I, w, g, h);
  const State ref = reference(I, w, g, h);
  EXPECT_EQ(int(o.path), int(expected));
  const double scale = w.norm();
  EXPECT_LT((o.w - ref.head<3>()).norm(), tol * scale)
      << "I " << I.transpose() << " w " << w.transpose() << " h " << h;
  EXPECT_LT((o.g - ref.tail<3>()).norm(), tol)
      << "I " << I.transpose() << " w " << w.transpose() << " h " << h;
}

TEST(FreeRigidBodyFlow, MatchesTinyStepGauss6AllOrderingsBothSidesOfTheSeparatrix) {
  const std::array<Vector3d, 6> orderings{Vector3d(1.0, 1.7, 2.2), Vector3d(1.0, 2.2, 1.7),
                                          Vector3d(1.7, 1.0, 2.2), Vector3d(1.7, 2.2, 1.0),
                                          Vector3d(2.2, 1.0, 1.7), Vector3d(2.2, 1.7, 1.0)};
  test::Random rng;
  int above = 0, below = 0;
  for (const Vector3d& I : orderings) {
    for (int trial = 0; trial < 4; ++trial) {
      const Vector3d w = rng.vec(-1.5, 1.5);
      const Vector3d g = rng.unit();
      (side(I, w) > 0 ? above : below)++;
      for (double h : {0.01, 0.37, 2.5, 23.0})  // the last is several periods
        expect_matches_reference(I, w, g, h, 1e-12, Path::elliptic);
    }
  }
  EXPECT_GT(above, 3);
  EXPECT_GT(below, 3);
}

TEST(FreeRigidBodyFlow, BothSidesCloseToTheSeparatrixAndNegativeSteps) {
  const Vector3d I(1.0, 2.0, 3.0);
  const Vector3d g = Vector3d(0.3, -0.5, 0.8).normalized();
  // Omega close to the middle axis, either side: M^2 - 2E I2 = I1 w1^2 (I1 - I2) + I3 w3^2 (I3 - I2).
  for (double w3 : {0.3, 0.1001, 0.0999, 0.03}) {
    const Vector3d w(0.1, 1.0, w3);
    for (double h : {0.5, 7.0, -3.0}) expect_matches_reference(I, w, g, h, 2e-12, Path::elliptic);
  }
}

TEST(FreeRigidBodyFlow, OnTheSeparatrixFallsBackToATinyStepIntegration) {
  const Vector3d I(1.0, 2.0, 3.0);
  const Vector3d g = Vector3d(0.3, -0.5, 0.8).normalized();
  // I1 w1^2 (I1 - I2) + I3 w3^2 (I3 - I2) = 0: w1^2 = 3 w3^2.
  const Vector3d w(std::sqrt(3.0) * 0.2, 0.9, 0.2);
  ASSERT_LT(std::abs(side(I, w)), FreeRigidBodyFlow::separatrix_tol);
  expect_matches_reference(I, w, g, 1.3, 1e-11, Path::separatrix);
  // Pure rotation about the middle axis perturbed slightly.
  expect_matches_reference(I, Vector3d(1e-12, 1.0, 0.0), g, 2.0, 1e-11, Path::separatrix);
}

TEST(FreeRigidBodyFlow, DegenerateCases) {
  const Vector3d g = Vector3d(0.3, -0.5, 0.8).normalized();
  // Equal moments: regular precession (each pair, and a sphere).
  for (const Vector3d& I : {Vector3d(1.0, 1.0, 2.0), Vector3d(1.5, 1.0, 1.0),
                            Vector3d(1.2, 0.7, 1.2), Vector3d(1.3, 1.3, 1.3)})
    for (double h : {0.2, 9.0})
      expect_matches_reference(I, Vector3d(0.7, -0.4, 1.1), g, h, 1e-12, Path::symmetric);
  // Steady rotation about each principal axis.
  for (int k = 0; k < 3; ++k)
    expect_matches_reference(Vector3d(1.0, 2.0, 3.0), 1.3 * Vector3d::Unit(k), g, 4.0, 1e-12,
                             Path::steady);
  // Nearly steady rotation about the largest and the smallest axis (elliptic, tiny amplitude).
  expect_matches_reference(Vector3d(1.0, 2.0, 3.0), Vector3d(1e-9, 2e-9, 1.0), g, 5.0, 1e-12,
                           Path::elliptic);
  expect_matches_reference(Vector3d(1.0, 2.0, 3.0), Vector3d(1.0, -1e-9, 2e-9), g, 5.0, 1e-12,
                           Path::elliptic);
  // At rest.
  EXPECT_EQ(int(flow(Vector3d(1.0, 2.0, 3.0), Vector3d::Zero(), g, 1.0).path), int(Path::rest));
}

TEST(FreeRigidBodyFlow, ConservesInvariantsToRoundOff) {
  const Vector3d I(1.0, 1.7, 2.2);
  test::Random rng;
  for (int trial = 0; trial < 200; ++trial) {
    const Vector3d w = rng.vec(), g = rng.unit();
    const double h = rng.uniform(-50.0, 50.0);
    const Out o = flow(I, w, g, h);
    const Vector3d m0 = I.cwiseProduct(w), m1 = I.cwiseProduct(o.w);
    EXPECT_NEAR(o.g.squaredNorm(), 1.0, 4e-15);
    EXPECT_NEAR(m1.norm(), m0.norm(), 4e-15 * m0.norm());
    EXPECT_NEAR(m1.dot(o.w), m0.dot(w), 8e-15 * m0.dot(w));
    EXPECT_NEAR(m1.dot(o.g), m0.dot(g), 8e-15 * m0.norm());
  }
}

TEST(FreeRigidBodyFlow, IsAOneParameterGroup) {
  test::Random rng;
  for (const Vector3d& I :
       {Vector3d(1.0, 1.7, 2.2), Vector3d(2.2, 1.0, 1.7), Vector3d(1.0, 1.0, 2.0)}) {
    for (int trial = 0; trial < 50; ++trial) {
      const Vector3d w = rng.vec(), g = rng.unit();
      const double h1 = rng.uniform(-5.0, 5.0), h2 = rng.uniform(-5.0, 5.0);
      const Out a = flow(I, w, g, h1);
      const Out ab = flow(I, a.w, a.g, h2);
      const Out c = flow(I, w, g, h1 + h2);
      EXPECT_LT((ab.w - c.w).norm(), 1e-12 * w.norm());
      EXPECT_LT((ab.g - c.g).norm(), 1e-12);
      // And h then -h is the identity.
      const Out back = flow(I, a.w, a.g, -h1);
      EXPECT_LT((back.w - w).norm(), 1e-12 * w.norm());
      EXPECT_LT((back.g - g).norm(), 1e-12);
    }
  }
}

TEST(ExactSplitSystem, KickAndFreeFlowKeepCasimirs) {
  const Body body{Vector3d(1.0, 1.7, 2.2), Vector3d(0.4, -0.3, 0.6), 1.5};
  const ExactSplitSystem sys(body);
  test::Random rng;
  for (int trial = 0; trial < 50; ++trial) {
    State x;
    x << rng.vec(), rng.unit();
    for (int i = 0; i < ExactSplitSystem::n_flows; ++i) {
      State y = x;
      sys.flow(i, rng.uniform(-0.5, 0.5), y);
      EXPECT_NEAR(y.tail<3>().squaredNorm(), 1.0, 4e-15);
      const double c0 = body.inertia.cwiseProduct(x.head<3>()).dot(x.tail<3>());
      const double c1 = body.inertia.cwiseProduct(y.head<3>()).dot(y.tail<3>());
      EXPECT_NEAR(c1, c0, 1e-14 * (1.0 + body.inertia.cwiseProduct(x.head<3>()).norm()));
    }
  }
}

}  // namespace
}  // namespace epviz::physics
