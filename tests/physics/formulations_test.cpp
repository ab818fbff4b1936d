// The Riccati and spinor formulations against the Poisson equations (1.2):
// their gamma maps (written here from math.md), differentiated by complex-step
// along the formulation's rhs, must give gamma x Omega.
#include <gtest/gtest.h>

#include <complex>

#include "helpers.hpp"
#include "physics/direct.hpp"
#include "physics/riccati.hpp"
#include "physics/spinor.hpp"
#include "physics/stereographic.hpp"

namespace epviz::physics {
namespace {

using cd = std::complex<double>;
using test::Random;
using test::random_body;

// math.md (3.4), sigma = 1.
template <class T>
Eigen::Matrix<T, 3, 1> gamma_north(T a, T b) {
  const T d = T(1) + a * a + b * b;
  return Eigen::Matrix<T, 3, 1>(T(-2) * a / d, T(-2) * b / d, (T(1) - a * a - b * b) / d);
}
// math.md section 3 remedy 1: w = u + i v.
template <class T>
Eigen::Matrix<T, 3, 1> gamma_south(T u, T v) {
  const T d = T(1) + u * u + v * v;
  return Eigen::Matrix<T, 3, 1>(T(-2) * u / d, T(2) * v / d, (u * u + v * v - T(1)) / d);
}
// The Hopf map of math.md written in real components.
template <class T>
Eigen::Matrix<T, 3, 1> hopf(T pr, T pi, T qr, T qi) {
  const T n = pr * pr + pi * pi + qr * qr + qi * qi;
  const T re = pr * qr + pi * qi, im = pi * qr - pr * qi;  // p conj(q)
  return Eigen::Matrix<T, 3, 1>(T(-2) * re / n, T(-2) * im / n,
                                (qr * qr + qi * qi - pr * pr - pi * pi) / n);
}

constexpr double kStep = 1e-30;  // complex step: exact derivatives, no cancellation

TEST(Riccati, ChainRuleNorthChartGivesPoisson) {
  Random rng;
  for (int trial = 0; trial < 200; ++trial) {
    const Body body = random_body(rng);
    RiccatiSystem sys(body);
    sys.set_chart(Chart::north);
    RiccatiSystem::State x;
    x << rng.vec(), rng.uniform(-3, 3), rng.uniform(-3, 3);
    RiccatiSystem::State dx;
    sys.rhs(0.0, x, dx);
    const double a = x[3], b = x[4];
    const Eigen::Vector3d da = gamma_north(cd(a, kStep), cd(b)).imag() / kStep;
    const Eigen::Vector3d db = gamma_north(cd(a), cd(b, kStep)).imag() / kStep;
    const Eigen::Vector3d gdot = da * dx[3] + db * dx[4];
    const Eigen::Vector3d g = gamma_north(a, b);
    const Eigen::Vector3d w = x.head<3>();
    EXPECT_LT((gdot - g.cross(w)).norm(), 1e-13 * (1 + w.norm())) << "trial " << trial;
    EXPECT_LT((sys.gamma(x) - g).norm(), 1e-15);
  }
}

TEST(Riccati, ChainRuleSouthChartGivesPoisson) {
  Random rng;
  for (int trial = 0; trial < 200; ++trial) {
    const Body body = random_body(rng);
    RiccatiSystem sys(body);
    sys.set_chart(Chart::south);
    RiccatiSystem::State x;
    x << rng.vec(), rng.uniform(-3, 3), rng.uniform(-3, 3);
    RiccatiSystem::State dx;
    sys.rhs(0.0, x, dx);
    const double u = x[3], v = x[4];
    const Eigen::Vector3d du = gamma_south(cd(u, kStep), cd(v)).imag() / kStep;
    const Eigen::Vector3d dv = gamma_south(cd(u), cd(v, kStep)).imag() / kStep;
    const Eigen::Vector3d gdot = du * dx[3] + dv * dx[4];
    const Eigen::Vector3d g = gamma_south(u, v);
    const Eigen::Vector3d w = x.head<3>();
    EXPECT_LT((gdot - g.cross(w)).norm(), 1e-13 * (1 + w.norm())) << "trial " << trial;
    EXPECT_LT((sys.gamma(x) - g).norm(), 1e-15);
    // The south chart is the inversion of the north one: eta = 1 / w.
    const cd eta = 1.0 / cd(u, v);
    EXPECT_LT((gamma_north(eta.real(), eta.imag()) - g).norm(), 1e-14);
    EXPECT_LT(std::abs(sys.eta(x) - eta), 1e-14 * std::abs(eta));
  }
}

TEST(Spinor, ChainRuleThroughHopfMapGivesPoisson) {
  Random rng;
  for (int trial = 0; trial < 200; ++trial) {
    const Body body = random_body(rng);
    SpinorSystem sys(body);
    SpinorSystem::State x;
    x << rng.vec(), rng.vec(-1, 1), rng.uniform(-1, 1);
    SpinorSystem::State dx;
    sys.rhs(0.0, x, dx);
    Eigen::Vector3d gdot = Eigen::Vector3d::Zero();
    for (int k = 0; k < 4; ++k) {
      cd c[4] = {cd(x[3]), cd(x[4]), cd(x[5]), cd(x[6])};
      c[k] += cd(0, kStep);
      gdot += hopf(c[0], c[1], c[2], c[3]).imag() / kStep * dx[3 + k];
    }
    const Eigen::Vector3d g = hopf(x[3], x[4], x[5], x[6]);
    const Eigen::Vector3d w = x.head<3>();
    EXPECT_LT((gdot - g.cross(w)).norm(), 1e-13 * (1 + w.norm())) << "trial " << trial;
    EXPECT_LT((sys.gamma(x) - g).norm(), 1e-15);
    // The linear flow is in SU(2): |p|^2 + |q|^2 is constant.
    EXPECT_LT(std::abs(x.tail<4>().dot(dx.tail<4>())),
              1e-14 * (1 + w.norm()) * x.tail<4>().squaredNorm());
  }
}

TEST(Spinor, LinearSystemIsTheRiccatiEquationOfEta) {
  // eta = p / q satisfies eta' = alpha eta^2 + beta eta + delta (math.md 3.3).
  Random rng;
  for (int trial = 0; trial < 100; ++trial) {
    SpinorSystem sys(random_body(rng));
    SpinorSystem::State x, dx;
    x << rng.vec(), rng.vec(-1, 1), rng.uniform(0.3, 1);
    sys.rhs(0.0, x, dx);
    const cd p(x[3], x[4]), q(x[5], x[6]), dp(dx[3], dx[4]), dq(dx[5], dx[6]);
    const cd eta = p / q, deta = (dp * q - p * dq) / (q * q);
    const double w1 = x[0], w2 = x[1], w3 = x[2];
    const cd alpha(w2 / 2, w1 / 2), beta(0, -w3), delta(w2 / 2, -w1 / 2);
    const cd expected = alpha * eta * eta + beta * eta + delta;
    EXPECT_LT(std::abs(deta - expected), 1e-12 * (1 + std::abs(expected)));
  }
}

TEST(Formulations, SameOmegaDotAndEulerEquations) {
  Random rng;
  for (int trial = 0; trial < 100; ++trial) {
    const Body body = random_body(rng);
    const InitialState s{rng.vec(), rng.unit()};
    DirectSystem d(body);
    RiccatiSystem r(body);
    SpinorSystem sp(body);
    const auto xd = d.pack(s);
    const auto xr = r.pack(s);
    const auto xs = sp.pack(s);
    EXPECT_LT((r.gamma(xr) - s.gamma).norm(), 1e-14);
    EXPECT_LT((sp.gamma(xs) - s.gamma).norm(), 1e-14);
    EXPECT_EQ(r.omega(xr), s.omega);
    EXPECT_EQ(sp.omega(xs), s.omega);
    DirectSystem::State dd;
    RiccatiSystem::State dr;
    SpinorSystem::State ds;
    d.rhs(0, xd, dd);
    r.rhs(0, xr, dr);
    sp.rhs(0, xs, ds);
    // (1.1) written out component by component.
    const Eigen::Vector3d& I = body.inertia;
    const Eigen::Vector3d& w = s.omega;
    const Eigen::Vector3d& g = s.gamma;
    const double P = body.weight, a0 = body.com.x(), b0 = body.com.y(), c0 = body.com.z();
    const Eigen::Vector3d expected(
        (-(I.z() - I.y()) * w.y() * w.z() + P * (g.y() * c0 - g.z() * b0)) / I.x(),
        (-(I.x() - I.z()) * w.z() * w.x() + P * (g.z() * a0 - g.x() * c0)) / I.y(),
        (-(I.y() - I.x()) * w.x() * w.y() + P * (g.x() * b0 - g.y() * a0)) / I.z());
    EXPECT_LT((dd.head<3>() - expected).norm(), 1e-13 * (1 + expected.norm()));
    EXPECT_LT((dr.head<3>() - expected).norm(), 1e-13 * (1 + expected.norm()));
    EXPECT_LT((ds.head<3>() - expected).norm(), 1e-13 * (1 + expected.norm()));
    EXPECT_LT((dd.tail<3>() - g.cross(w)).norm(), 1e-14 * (1 + w.norm()));
  }
}

TEST(Stereographic, RoundTripAndPole) {
  Random rng;
  for (int trial = 0; trial < 100; ++trial) {
    const Eigen::Vector3d g = rng.unit();
    const auto ab = stereographic(g);
    ASSERT_TRUE(ab.has_value());
    EXPECT_LT((from_stereographic(ab->x(), ab->y()) - g).norm(), 1e-12 / (1 + g.z()));
    EXPECT_LT((gamma_north(ab->x(), ab->y()) - g).norm(), 1e-12 / (1 + g.z()));
  }
  EXPECT_FALSE(stereographic(Eigen::Vector3d(0, 0, -1)).has_value());
  EXPECT_EQ(from_stereographic(0, 0), Eigen::Vector3d(0, 0, 1));
}

TEST(Riccati, PackPicksChartByEtaModulus) {
  const Body body;
  RiccatiSystem sys(body);
  auto x = sys.pack({Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(0.6, 0, 0.8)});
  EXPECT_EQ(sys.chart(), Chart::north);
  EXPECT_LE(std::hypot(x[3], x[4]), 1.0);
  x = sys.pack({Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(0.6, 0, -0.8)});
  EXPECT_EQ(sys.chart(), Chart::south);
  EXPECT_LE(std::hypot(x[3], x[4]), 1.0);
  EXPECT_LT((sys.gamma(x) - Eigen::Vector3d(0.6, 0, -0.8)).norm(), 1e-15);
  x = sys.pack({Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(0, 0, -1)});
  EXPECT_EQ(sys.chart(), Chart::south);
  EXPECT_EQ(sys.gamma(x), Eigen::Vector3d(0, 0, -1));
}

TEST(Riccati, ChartSwitchKeepsGammaWithHysteresis) {
  const Body body;
  RiccatiSystem sys(body);
  sys.set_chart(Chart::north);
  RiccatiSystem::State x;
  // Inside the band: |eta| = 1.5 stays in the north chart.
  x << 1, 2, 3, 0.9, -1.2;
  RiccatiSystem::State y = x;
  EXPECT_FALSE(sys.regularize(y));
  EXPECT_EQ(y, x);
  EXPECT_EQ(sys.chart(), Chart::north);
  // |eta| = 2.5 > 2: switch to w = 1/eta, gamma unchanged.
  x << 1, 2, 3, 1.5, -2.0;
  Eigen::Vector3d g = sys.gamma(x);
  EXPECT_TRUE(sys.regularize(x));
  EXPECT_EQ(sys.chart(), Chart::south);
  EXPECT_EQ(sys.chart_switches(), 1);
  EXPECT_LT((sys.gamma(x) - g).norm(), 1e-14);
  EXPECT_NEAR(std::hypot(x[3], x[4]), 0.4, 1e-15);
  EXPECT_EQ(x.head<3>(), Eigen::Vector3d(1, 2, 3));
  // Inside the band in the south chart: |w| = 1.5 (|eta| = 2/3) does not switch back.
  x[3] = 0.9;
  x[4] = 1.2;
  EXPECT_FALSE(sys.regularize(x));
  EXPECT_EQ(sys.chart(), Chart::south);
  // |w| = 2.5 switches back.
  x[3] = -2.0;
  x[4] = 1.5;
  g = sys.gamma(x);
  EXPECT_TRUE(sys.regularize(x));
  EXPECT_EQ(sys.chart(), Chart::north);
  EXPECT_EQ(sys.chart_switches(), 2);
  EXPECT_LT((sys.gamma(x) - g).norm(), 1e-14);
  // Random states on both sides.
  Random rng;
  for (int trial = 0; trial < 100; ++trial) {
    x << rng.vec(), rng.uniform(-50, 50), rng.uniform(-50, 50);
    if (std::hypot(x[3], x[4]) <= 2.0) continue;
    const Eigen::Vector3d before = sys.gamma(x);
    ASSERT_TRUE(sys.regularize(x));
    EXPECT_LT((sys.gamma(x) - before).norm(), 1e-14);
  }
  EXPECT_EQ(sys.check(x), std::nullopt);
}

TEST(Riccati, NoSwitchReportsThePole) {
  const Body body;
  RiccatiSystem sys(body, false);
  RiccatiSystem::State x;
  x << 1, 2, 3, 1e5, 0;
  EXPECT_FALSE(sys.regularize(x));
  EXPECT_FALSE(sys.check(x).has_value());
  x[3] = 2e6;
  EXPECT_FALSE(sys.regularize(x));
  EXPECT_EQ(sys.chart(), Chart::north);
  const auto issue = sys.check(x);
  ASSERT_TRUE(issue.has_value());
  EXPECT_EQ(issue->kind, epviz::numerics::FailureKind::chart_pole);
  EXPECT_NE(issue->detail.find("pole"), std::string::npos) << issue->detail;
  // A plain fact: what to do about it is worded by the front ends.
  EXPECT_EQ(issue->detail.find("--"), std::string::npos) << issue->detail;
  EXPECT_EQ(sys.chart_switches(), 0);
}

TEST(Riccati, TrajectoryThroughSouthPoleMatchesDirect) {
  // gamma sweeps across the south pole: with chart switching the Riccati
  // trajectory follows the direct one.
  const Body body{Eigen::Vector3d(1.0, 1.5, 2.0), Eigen::Vector3d(0.1, 0.2, 0.3), 1.0};
  const InitialState s{Eigen::Vector3d(3.0, 0.2, 0.1), Eigen::Vector3d(0, 0.05, 1).normalized()};
  DirectSystem d(body);
  RiccatiSystem r(body);
  auto xd = d.pack(s);
  auto xr = r.pack(s);
  const auto fd = [&](double t, const DirectSystem::State& x) {
    DirectSystem::State dx;
    d.rhs(t, x, dx);
    return dx;
  };
  const auto fr = [&](double t, const RiccatiSystem::State& x) {
    RiccatiSystem::State dx;
    r.rhs(t, x, dx);
    return dx;
  };
  const double h = 1e-3;
  double max_err = 0, min_g3 = 1;
  for (int i = 0; i < 5000; ++i) {
    r.regularize(xr);
    xd = test::rk4_step(fd, i * h, xd, h);
    xr = test::rk4_step(fr, i * h, xr, h);
    max_err = std::max(max_err, (r.gamma(xr) - xd.tail<3>()).norm());
    min_g3 = std::min(min_g3, xd[5]);
  }
  EXPECT_LT(min_g3, -0.99);
  EXPECT_GE(r.chart_switches(), 2);
  EXPECT_LT(max_err, 1e-9);
}

}  // namespace
}  // namespace epviz::physics
