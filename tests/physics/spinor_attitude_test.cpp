// The spinor's attitude against an attitude integrated directly from
// dR/dt = R [Omega]x with a prescribed smooth Omega(t).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "helpers.hpp"
#include "physics/spinor.hpp"

namespace epviz::physics {
namespace {

using Eigen::Matrix3d;
using Eigen::Quaterniond;

Matrix3d hat(const Vector3d& w) {
  Matrix3d m;
  m << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  return m;
}

Vector3d prescribed_omega(double t) {
  return Vector3d(1.3 * std::sin(1.7 * t) + 0.2, 0.8 * std::cos(0.9 * t) - 0.5,
                  2.0 + 0.7 * std::sin(2.3 * t));
}

TEST(SpinorAttitude, FollowsRigidBodyKinematics) {
  const Body body{Vector3d(1, 2, 2.5), Vector3d(0.3, -0.2, 0.5), 1.0};
  const SpinorSystem sys(body);
  const Quaterniond q0 = Quaterniond(0.3, -0.5, 0.7, 0.2).normalized();
  SpinorSystem::State x = SpinorSystem::pack(prescribed_omega(0), q0);
  EXPECT_LT(q0.angularDistance(SpinorSystem::attitude(x)), 1e-15);

  // (p, q) part of the spinor rhs with Omega prescribed.
  using V4 = Eigen::Vector4d;
  const auto fpq = [&](double t, const V4& pq) {
    SpinorSystem::State s, ds;
    s << prescribed_omega(t), pq;
    sys.rhs(t, s, ds);
    return V4(ds.tail<4>());
  };
  const auto frot = [&](double t, const Matrix3d& r) {
    return Matrix3d(r * hat(prescribed_omega(t)));
  };

  V4 pq = x.tail<4>();
  Matrix3d R = q0.toRotationMatrix();
  const int n = 4000;
  const double h = 8.0 / n;
  double max_err = 0.0;
  for (int i = 0; i < n; ++i) {
    pq = test::rk4_step(fpq, i * h, pq, h);
    R = test::rk4_step(frot, i * h, R, h);
    if (i % 100 == 99) {
      SpinorSystem::State s;
      s << prescribed_omega((i + 1) * h), pq;
      const Quaterniond att = SpinorSystem::attitude(s);
      max_err = std::max(max_err, (att.toRotationMatrix() - R).norm());
      // attitude * gamma == e_z, with gamma by the Hopf map.
      EXPECT_LT((att * SpinorSystem::gamma(s) - Vector3d::UnitZ()).norm(), 1e-14);
      // The space vertical seen in the body is R^T e_z.
      EXPECT_LT((SpinorSystem::gamma(s) - R.transpose() * Vector3d::UnitZ()).norm(), 1e-9);
    }
  }
  EXPECT_LT(max_err, 1e-9);
  // The attitude really turned (not a trivially constant rotation).
  EXPECT_GT((R - q0.toRotationMatrix()).norm(), 0.5);
}

TEST(SpinorAttitude, AttitudeDerivativeIsRTimesOmegaHat) {
  // Instantaneous check: d/dt attitude(x) = attitude(x) [Omega]x along the rhs.
  test::Random rng;
  const Body body{Vector3d(1, 2, 2.5), Vector3d(0.3, -0.2, 0.5), 1.0};
  const SpinorSystem sys(body);
  for (int trial = 0; trial < 50; ++trial) {
    const Quaterniond q(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1),
                        rng.uniform(-1, 1));
    SpinorSystem::State x = SpinorSystem::pack(rng.vec(), q);
    SpinorSystem::State dx;
    sys.rhs(0, x, dx);
    const double eps = 1e-6;
    const Matrix3d rp = SpinorSystem::attitude(x + eps * dx).toRotationMatrix();
    const Matrix3d rm = SpinorSystem::attitude(x - eps * dx).toRotationMatrix();
    const Matrix3d rdot = (rp - rm) / (2 * eps);
    const Matrix3d r = SpinorSystem::attitude(x).toRotationMatrix();
    EXPECT_LT((rdot - r * hat(x.head<3>())).norm(), 1e-8 * (1 + x.head<3>().norm()));
  }
}

TEST(SpinorAttitude, PackFromGammaIsTheShortestArc) {
  test::Random rng;
  for (int trial = 0; trial < 100; ++trial) {
    const InitialState s{rng.vec(), rng.unit()};
    const SpinorSystem::State x = SpinorSystem::pack(s);
    EXPECT_NEAR(SpinorSystem::norm2(x), 1.0, 1e-15);
    EXPECT_EQ(x.head<3>(), s.omega);
    EXPECT_LT((SpinorSystem::gamma(x) - s.gamma).norm(), 1e-14);
    const Quaterniond att = SpinorSystem::attitude(x);
    EXPECT_LT((att * s.gamma - Vector3d::UnitZ()).norm(), 1e-14);
    // Shortest arc: the rotation angle is the angle between gamma and e_z.
    const double angle = std::acos(std::clamp(s.gamma.z(), -1.0, 1.0));
    EXPECT_NEAR(Eigen::AngleAxisd(att).angle(), angle, 1e-7);
  }
  // gamma = e_z: the identity.
  const SpinorSystem::State x = SpinorSystem::pack(InitialState{});
  EXPECT_LT(SpinorSystem::attitude(x).angularDistance(Quaterniond::Identity()), 1e-15);
}

TEST(SpinorAttitude, PackAttitudeRoundTrip) {
  test::Random rng;
  for (int trial = 0; trial < 100; ++trial) {
    const Quaterniond q =
        Quaterniond(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1))
            .normalized();
    const Vector3d w = rng.vec();
    const SpinorSystem::State x = SpinorSystem::pack(w, q);
    EXPECT_LT(SpinorSystem::attitude(x).angularDistance(q), 1e-7);
    EXPECT_LT((SpinorSystem::attitude(x).toRotationMatrix() - q.toRotationMatrix()).norm(), 1e-14);
    // The Hopf map gives the body-frame vertical of that attitude.
    EXPECT_LT((SpinorSystem::gamma(x) - q.inverse() * Vector3d::UnitZ()).norm(), 1e-14);
    // The overall sign of (p, q) is the same rotation.
    EXPECT_LT(
        (SpinorSystem::attitude(SpinorSystem::State(-x)).toRotationMatrix() - q.toRotationMatrix())
            .norm(),
        1e-14);
  }
}

}  // namespace
}  // namespace epviz::physics
