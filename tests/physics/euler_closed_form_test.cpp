// The torque-free closed form against the Euler equations and an RK4 written here.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

#include "helpers.hpp"
#include "physics/euler_closed_form.hpp"

namespace epviz::physics {
namespace {

using Eigen::Vector3d;

Vector3d euler_rhs(const Vector3d& I, const Vector3d& w) {
  return Vector3d((I.y() - I.z()) * w.y() * w.z() / I.x(), (I.z() - I.x()) * w.z() * w.x() / I.y(),
                  (I.x() - I.y()) * w.x() * w.y() / I.z());
}

Vector3d rk4_euler(const Vector3d& I, Vector3d w, double t, int n) {
  const auto f = [&](double, const Vector3d& x) { return euler_rhs(I, x); };
  return test::rk4(f, 0.0, t, w, n);
}

TEST(EulerClosedForm, MathMdCheckAgainstRk4) {
  const Vector3d I(1, 2, 3), w0(0.4, 0, 1);
  const EulerClosedForm cf(I, w0);
  const Vector3d ref = rk4_euler(I, w0, 10.0, 20000);
  EXPECT_LT((cf.omega(10.0) - ref).norm(), 1e-10);
  EXPECT_LT((cf.omega(0.0) - w0).norm(), 1e-14);
}

// Both regimes in all six orderings of (1, 2, 3).
TEST(EulerClosedForm, AllOrderingsAndBothRegimes) {
  int perm[3] = {0, 1, 2};
  const Vector3d base(1, 2, 3);
  int cases = 0;
  do {
    const Vector3d I(base[perm[0]], base[perm[1]], base[perm[2]]);
    const int imin = std::min_element(I.data(), I.data() + 3) - I.data();
    const int imax = std::max_element(I.data(), I.data() + 3) - I.data();
    for (int regime = 0; regime < 2; ++regime) {
      for (int signs = 0; signs < 8; signs += 3) {
        // Mostly about the largest (regime 0) or the smallest (regime 1) axis.
        Vector3d w0(0.5, -0.6, 0.7);
        w0[regime == 0 ? imax : imin] = 1.6;
        for (int k = 0; k < 3; ++k)
          if (signs & (1 << k)) w0[k] = -w0[k];
        const double m2 = I.cwiseProduct(w0).squaredNorm(), e2 = I.cwiseProduct(w0).dot(w0);
        ASSERT_EQ(m2 > 2.0 * e2, regime == 0);  // I_mid = 2
        const EulerClosedForm cf(I, w0);
        EXPECT_EQ(cf.dominant_axis(), regime == 0 ? imax : imin);
        EXPECT_LT((cf.omega(0) - w0).norm(), 1e-13) << I.transpose() << " / " << w0.transpose();
        // The Euler equations by central differences.
        const double h = 1e-4;
        for (double t : {0.0, 0.37, 1.9, 4.2, 11.3, -3.1}) {
          const Vector3d dw = (cf.omega(t + h) - cf.omega(t - h)) / (2 * h);
          EXPECT_LT((dw - euler_rhs(I, cf.omega(t))).norm(), 1e-7)
              << "I = " << I.transpose() << " w0 = " << w0.transpose() << " t = " << t;
        }
        // And an independent integration.
        EXPECT_LT((cf.omega(3.0) - rk4_euler(I, w0, 3.0, 6000)).norm(), 1e-10)
            << "I = " << I.transpose() << " w0 = " << w0.transpose();
        // Periodic with the period it reports.
        EXPECT_LT((cf.omega(cf.period()) - w0).norm(), 1e-11);
        ++cases;
      }
    }
  } while (std::next_permutation(perm, perm + 3));
  EXPECT_EQ(cases, 6 * 2 * 3);
}

TEST(EulerClosedForm, NearSeparatrixAndPureRotation) {
  const Vector3d I(1, 2, 3);
  // Close to the separatrix (m close to 1) on either side.
  for (double eps : {1e-3, -1e-3}) {
    const Vector3d w0(std::sqrt(3.0) * (1 - eps), 0.5, 1.0);
    const EulerClosedForm cf(I, w0);
    EXPECT_GT(cf.modulus(), 0.99);
    EXPECT_LT((cf.omega(2.0) - rk4_euler(I, w0, 2.0, 8000)).norm(), 1e-9);
  }
  // Steady rotation about the largest and the smallest axes.
  for (const Vector3d& w0 : {Vector3d(0, 0, 1.5), Vector3d(-2, 0, 0)}) {
    const EulerClosedForm cf(I, w0);
    EXPECT_LT((cf.omega(7.0) - w0).norm(), 1e-14);
  }
}

TEST(EulerClosedForm, RejectsDegenerateInput) {
  EXPECT_THROW(EulerClosedForm(Vector3d(1, 1, 3), Vector3d(1, 2, 3)), std::invalid_argument);
  EXPECT_THROW(EulerClosedForm(Vector3d(1, 3, 3), Vector3d(1, 2, 3)), std::invalid_argument);
  EXPECT_THROW(EulerClosedForm(Vector3d(0, 2, 3), Vector3d(1, 2, 3)), std::invalid_argument);
  EXPECT_THROW(EulerClosedForm(Vector3d(1, 2, 3), Vector3d(0, 0, 0)), std::invalid_argument);
  // Exactly on the separatrix: M^2 = 2 E I2.
  EXPECT_THROW(EulerClosedForm(Vector3d(1, 2, 3), Vector3d(0, 1, 0)), std::invalid_argument);
  EXPECT_THROW(EulerClosedForm(Vector3d(1, 2, 3), Vector3d(std::sqrt(3.0), 0.5, 1.0)),
               std::invalid_argument);
  EXPECT_THROW(EulerClosedForm(Vector3d(3, 1, 2), Vector3d(1.0, std::sqrt(3.0), 0.5)),
               std::invalid_argument);
}

}  // namespace
}  // namespace epviz::physics
