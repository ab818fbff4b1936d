// The exact sub-flows of DirectSystem (Lie-Poisson splitting).
#include <gtest/gtest.h>

#include "helpers.hpp"
#include "physics/direct.hpp"

namespace epviz::physics {
namespace {

using State = DirectSystem::State;

Body test_body() { return Body{Vector3d(1.0, 1.7, 2.2), Vector3d(0.4, -0.3, 0.6), 1.5}; }

double area(const Body& b, const State& x) {
  return b.inertia.cwiseProduct(x.head<3>()).dot(x.tail<3>());
}

TEST(Splitting, SubFlowsConserveCasimirs) {
  const Body body = test_body();
  const DirectSystem sys(body);
  test::Random rng;
  for (int trial = 0; trial < 100; ++trial) {
    State x;
    x << rng.vec(), rng.unit();
    for (int i = 0; i < DirectSystem::n_flows; ++i) {
      State y = x;
      sys.flow(i, rng.uniform(-0.5, 0.5), y);
      EXPECT_NEAR(y.tail<3>().squaredNorm(), 1.0, 2e-15) << "flow " << i;
      const double scale = body.inertia.cwiseProduct(x.head<3>()).norm();
      EXPECT_NEAR(area(body, y), area(body, x), 1e-14 * (1 + scale)) << "flow " << i;
    }
  }
}

TEST(Splitting, KickIsExact) {
  const Body body = test_body();
  const DirectSystem sys(body);
  test::Random rng;
  for (int trial = 0; trial < 50; ++trial) {
    State x;
    x << rng.vec(), rng.unit();
    const double h = rng.uniform(-1, 1);
    State y = x;
    sys.flow(0, h, y);
    const Vector3d g = x.tail<3>();
    const Vector3d torque = body.weight * g.cross(body.com);  // -r x P gamma
    const Vector3d expected = x.head<3>() + h * torque.cwiseQuotient(body.inertia);
    EXPECT_LT((y.head<3>() - expected).norm(), 1e-15 * (1 + expected.norm()));
    EXPECT_EQ(y.tail<3>(), g);
  }
}

TEST(Splitting, RotationFlowsSolveTheirSubProblems) {
  // Sub-problem i: H = T_i = 1/2 I_i Omega_i^2, i.e. M' = M x (Omega_i e_i),
  // gamma' = gamma x (Omega_i e_i), with M = I Omega.
  const Body body = test_body();
  const DirectSystem sys(body);
  test::Random rng;
  for (int i = 1; i <= 3; ++i) {
    const Vector3d e = Vector3d::Unit(i - 1);
    const auto f = [&](double, const State& x) {
      const Vector3d w = x.head<3>();
      const Vector3d m = body.inertia.cwiseProduct(w);
      const Vector3d axis = w[i - 1] * e;
      State dx;
      dx << m.cross(axis).cwiseQuotient(body.inertia), Vector3d(x.tail<3>()).cross(axis);
      return dx;
    };
    for (int trial = 0; trial < 10; ++trial) {
      State x;
      x << rng.vec(), rng.unit();
      const double h = rng.uniform(0.1, 1.0);
      State y = x;
      sys.flow(i, h, y);
      const State ref = test::rk4(f, 0.0, h, x, 2000);
      EXPECT_LT((y - ref).norm(), 1e-12) << "flow " << i;
      EXPECT_GT((y - x).norm(), 1e-3);  // something happened
    }
  }
}

TEST(Splitting, StrangCompositionIsSecondOrder) {
  const Body body = test_body();
  const DirectSystem sys(body);
  State x0;
  x0 << 0.7, -0.4, 1.1, Vector3d(0.3, 0.5, 0.8).normalized();
  const auto f = [&](double t, const State& x) {
    State dx;
    sys.rhs(t, x, dx);
    return dx;
  };
  const double T = 1.0;
  const State ref = test::rk4(f, 0.0, T, x0, 4000);
  double err[2];
  for (int k = 0; k < 2; ++k) {
    const int n = 100 << k;
    State x = x0;
    for (int s = 0; s < n; ++s) sys.strang_step(T / n, x);
    err[k] = (x - ref).norm();
  }
  EXPECT_NEAR(err[0] / err[1], 4.0, 0.2);
  EXPECT_LT(err[1], 1e-3);
}

}  // namespace
}  // namespace epviz::physics
