// Andoyer–Deprit variables (docs/math.md §1.6) against oracles computed
// here: L, G, H from M = I Ω; the Lie–Poisson brackets of the new variables
// (canonical pairs (l, L), (g, G)), by finite differences; Hamilton's
// equations in the new variables, with the energy written here, against
// their rates along the Euler–Poisson flow; the inverse both ways; the
// singular set reported, never a number.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>

#include "physics/andoyer.hpp"
#include "physics/direct.hpp"

namespace epviz::physics {
namespace {

using Six = Eigen::Matrix<double, 6, 1>;  // (M, γ)

const Body kBody{{1.3, 2.1, 2.9}, {0.4, -0.3, 0.7}, 1.5};

// C1 of docs/math.md (1.5), written here from M.
double energy(const Body& b, const Vector3d& m, const Vector3d& gamma) {
  return 0.5 * m.cwiseProduct(m).cwiseQuotient(b.inertia).sum() + b.weight * b.com.dot(gamma);
}

// Random states well off the singular set (M not within 0.2 rad of e3 or of
// the vertical), with no angle within 0.1 of ±π, so that finite differences
// of the angles need no unwrapping.
std::vector<Six> states(int n) {
  std::mt19937 rng(12345);
  std::normal_distribution<double> normal;
  std::vector<Six> out;
  while (int(out.size()) < n) {
    Vector3d m(normal(rng), normal(rng), normal(rng));
    Vector3d gamma(normal(rng), normal(rng), normal(rng));
    m *= 1.5;
    gamma.normalize();
    const Vector3d omega = m.cwiseQuotient(kBody.inertia);
    const auto a = andoyer_variables(kBody, omega, gamma);
    if (!a.l || !a.g) continue;
    if (std::hypot(m.x(), m.y()) < 0.2 * a.G || gamma.cross(m).norm() < 0.2 * a.G) continue;
    if (std::abs(*a.l) > 3.0 || std::abs(*a.g) > 3.0) continue;
    Six x;
    x << m, gamma;
    out.push_back(x);
  }
  return out;
}

// The five variables as functions of (M, γ): l, L, g, G, H.
std::array<double, 5> variables(const Six& x) {
  const Vector3d omega = x.head<3>().cwiseQuotient(kBody.inertia);
  const auto a = andoyer_variables(kBody, omega, x.tail<3>());
  EXPECT_TRUE(a.l && a.g);
  return {a.l.value_or(NAN), a.L, a.g.value_or(NAN), a.G, a.H};
}

// The gradient of variable k at x, central differences.
Six gradient(int k, const Six& x, double h = 1e-6) {
  Six grad;
  for (int i = 0; i < 6; ++i) {
    Six up = x, down = x;
    up[i] += h;
    down[i] -= h;
    grad[i] = (variables(up)[std::size_t(k)] - variables(down)[std::size_t(k)]) / (2.0 * h);
  }
  return grad;
}

// The Lie–Poisson bracket of the heavy top in body axes, written here:
// {F, K} = −M·(∇_M F × ∇_M K) − γ·(∇_M F × ∇_γ K + ∇_γ F × ∇_M K), whose
// {x, C1} are (1.1)–(1.2) (checked below).
double bracket(const Six& x, const Six& df, const Six& dk) {
  const Vector3d m = x.head<3>(), gamma = x.tail<3>();
  const Vector3d fm = df.head<3>(), fg = df.tail<3>(), km = dk.head<3>(), kg = dk.tail<3>();
  return -m.dot(fm.cross(km)) - gamma.dot(fm.cross(kg) + fg.cross(km));
}

TEST(Andoyer, MomentaAreTheMomentumsComponents) {
  for (const Six& x : states(50)) {
    const Vector3d m = x.head<3>(), gamma = x.tail<3>();
    const Vector3d omega = m.cwiseQuotient(kBody.inertia);
    const auto a = andoyer_variables(kBody, omega, gamma);
    const double I3w3 = kBody.inertia.z() * omega.z();
    const double Iw = std::sqrt(std::pow(kBody.inertia.x() * omega.x(), 2) +
                                std::pow(kBody.inertia.y() * omega.y(), 2) + I3w3 * I3w3);
    const double Iw_gamma = kBody.inertia.x() * omega.x() * gamma.x() +
                            kBody.inertia.y() * omega.y() * gamma.y() + I3w3 * gamma.z();
    EXPECT_NEAR(a.L, I3w3, 1e-14);
    EXPECT_NEAR(a.G, Iw, 1e-14);
    EXPECT_NEAR(a.H, Iw_gamma, 1e-14);
    EXPECT_EQ(a.singularity, AndoyerSingularity::none);
  }
}

TEST(Andoyer, BracketWrittenHereGivesTheEquationsOfMotion) {
  // So that the brackets below are the top's: {M_i, C1}, {γ_i, C1} are
  // DirectSystem's rates (as M = I Ω').
  const DirectSystem sys(kBody);
  for (const Six& x : states(5)) {
    Six dE;
    dE << x.head<3>().cwiseQuotient(kBody.inertia), kBody.weight * kBody.com;
    DirectSystem::State s, ds;
    s << x.head<3>().cwiseQuotient(kBody.inertia), x.tail<3>();
    sys.rhs(0.0, s, ds);
    for (int i = 0; i < 6; ++i) {
      const Six e = Six::Unit(i);
      const double rate = i < 3 ? kBody.inertia[i] * ds[i] : ds[i];
      EXPECT_NEAR(bracket(x, e, dE), rate, 1e-12) << i;
    }
  }
}

TEST(Andoyer, PoissonBracketsAreCanonical) {
  // l, L, g, G, H: {l, L} = {g, G} = 1, every other pair 0 (H a Casimir).
  const char* names[] = {"l", "L", "g", "G", "H"};
  for (const Six& x : states(20)) {
    std::array<Six, 5> d;
    for (int k = 0; k < 5; ++k) d[std::size_t(k)] = gradient(k, x);
    for (int a = 0; a < 5; ++a)
      for (int b = a + 1; b < 5; ++b) {
        const double expected = (a == 0 && b == 1) || (a == 2 && b == 3) ? 1.0 : 0.0;
        EXPECT_NEAR(bracket(x, d[std::size_t(a)], d[std::size_t(b)]), expected, 1e-7)
            << "{" << names[a] << ", " << names[b] << "} at " << x.transpose();
      }
  }
}

TEST(Andoyer, HamiltonsEquationsMatchTheFlow) {
  const DirectSystem sys(kBody);
  for (const Six& x : states(20)) {
    const auto v = variables(x);
    const double H = v[4];
    // C1(l, L, g, G) on this level of H, through the inverse map.
    const auto E = [&](std::array<double, 4> q) {
      const InitialState s = andoyer_state(kBody, q[0], q[1], q[2], q[3], H);
      return energy(kBody, kBody.inertia.cwiseProduct(s.omega), s.gamma);
    };
    const std::array<double, 4> q{v[0], v[1], v[2], v[3]};
    std::array<double, 4> dE{};
    for (std::size_t i = 0; i < 4; ++i) {
      const double h = 1e-6;
      auto up = q, down = q;
      up[i] += h;
      down[i] -= h;
      dE[i] = (E(up) - E(down)) / (2.0 * h);
    }
    // The variables' rates along the flow: central differences along the
    // direct equations' vector field, in (M, γ).
    DirectSystem::State s, ds;
    s << x.head<3>().cwiseQuotient(kBody.inertia), x.tail<3>();
    sys.rhs(0.0, s, ds);
    Six dx;
    dx << kBody.inertia.cwiseProduct(ds.head<3>()), ds.tail<3>();
    const double dt = 1e-6;
    const auto after = variables(x + dt * dx), before = variables(x - dt * dx);
    std::array<double, 5> rate{};
    for (std::size_t k = 0; k < 5; ++k) rate[k] = (after[k] - before[k]) / (2.0 * dt);
    const double tol =
        1e-6 * (1.0 + std::abs(dE[0]) + std::abs(dE[1]) + std::abs(dE[2]) + std::abs(dE[3]));
    EXPECT_NEAR(rate[0], dE[1], tol) << "l' = dE/dL";
    EXPECT_NEAR(rate[1], -dE[0], tol) << "L' = -dE/dl";
    EXPECT_NEAR(rate[2], dE[3], tol) << "g' = dE/dG";
    EXPECT_NEAR(rate[3], -dE[2], tol) << "G' = -dE/dg";
    EXPECT_NEAR(rate[4], 0.0, tol) << "H' = 0";
  }
}

TEST(Andoyer, InverseRoundTrips) {
  for (const Six& x : states(50)) {
    const Vector3d omega = x.head<3>().cwiseQuotient(kBody.inertia);
    const auto a = andoyer_variables(kBody, omega, x.tail<3>());
    const InitialState s = andoyer_state(kBody, *a.l, a.L, *a.g, a.G, a.H);
    EXPECT_LT((s.omega - omega).norm(), 1e-13 * (1.0 + omega.norm()));
    EXPECT_LT((s.gamma - x.tail<3>()).norm(), 1e-13);
  }
  // And from the variables: a grid of angles over the whole circle.
  for (double l = -3.1; l < 3.2; l += 0.7)
    for (double g = -3.1; g < 3.2; g += 0.9) {
      const InitialState s = andoyer_state(kBody, l, 0.8, g, 1.7, -0.4);
      EXPECT_NEAR(s.gamma.norm(), 1.0, 1e-15);
      const auto a = andoyer_variables(kBody, s.omega, s.gamma);
      ASSERT_TRUE(a.l && a.g);
      EXPECT_NEAR(std::remainder(*a.l - l, 2 * std::numbers::pi), 0.0, 1e-13);  // mod 2π
      EXPECT_NEAR(std::remainder(*a.g - g, 2 * std::numbers::pi), 0.0, 1e-13);
      EXPECT_NEAR(a.L, 0.8, 1e-14);
      EXPECT_NEAR(a.G, 1.7, 1e-14);
      EXPECT_NEAR(a.H, -0.4, 1e-14);
    }
  EXPECT_THROW(andoyer_state(kBody, 0, 1.7, 0, 1.7, 0), std::invalid_argument);  // L = G
  EXPECT_THROW(andoyer_state(kBody, 0, 0, 0, 1, -1), std::invalid_argument);     // H = -G
  EXPECT_THROW(andoyer_state(kBody, 0, 0, 0, 0, 0), std::invalid_argument);      // G = 0
  EXPECT_THROW(andoyer_state(kBody, NAN, 0, 0, 1, 0), std::invalid_argument);
}

TEST(Andoyer, TheConventionsNodesAndRanges) {
  // M = (0, G sin i, G cos i): the node n2 = M × e3 is +e1, so l = 0; M along
  // +e1 puts n2 along −e2, a quarter turn short of e1: l = π/2.
  const Vector3d gamma(0.3, -0.5, std::sqrt(1 - 0.34));
  const auto at = [&](const Vector3d& m) {
    return andoyer_variables(kBody, m.cwiseQuotient(kBody.inertia), gamma);
  };
  EXPECT_NEAR(*at({0, 1, 1}).l, 0.0, 1e-15);
  EXPECT_NEAR(*at({1, 0, 1}).l, std::numbers::pi / 2, 1e-15);
  EXPECT_EQ(*at({0, -1, 1}).l, std::numbers::pi);  // never −π
  // g: cos g = (H L − γ3 G²) / (|γ × M| |M × e3|) (math.md (1.12)).
  const Vector3d m(0.4, -1.1, 0.6);
  const auto a = at(m);
  const double c = (m.dot(gamma) * m.z() - gamma.z() * m.squaredNorm()) /
                   (gamma.cross(m).norm() * std::hypot(m.x(), m.y()));
  EXPECT_NEAR(std::cos(*a.g), c, 1e-14);
  const auto sides =
      andoyer_angle_sides(AndoyerAngle::g, kBody, m.cwiseQuotient(kBody.inertia), gamma);
  EXPECT_NEAR(std::atan2(sides.sine, sides.cosine), *a.g, 1e-14);
}

TEST(Andoyer, SingularSetIsReportedNotANumber) {
  const Vector3d gamma(0.6, 0.0, 0.8);
  // At rest: G = 0, no angle.
  auto a = andoyer_variables(kBody, Vector3d::Zero(), gamma);
  EXPECT_EQ(a.singularity, AndoyerSingularity::no_momentum);
  EXPECT_FALSE(a.l || a.g);
  // Spinning about e3: L = G, neither l nor g.
  a = andoyer_variables(kBody, {0.0, 0.0, -2.0}, gamma);
  EXPECT_EQ(a.singularity, AndoyerSingularity::momentum_on_axis3);
  EXPECT_FALSE(a.l || a.g);
  EXPECT_EQ(a.L, -a.G);
  // M along the vertical: l defined, g not.
  a = andoyer_variables(kBody, (2.0 * gamma).cwiseQuotient(kBody.inertia), gamma);
  EXPECT_EQ(a.singularity, AndoyerSingularity::momentum_vertical);
  ASSERT_TRUE(a.l);
  EXPECT_FALSE(a.g);
  EXPECT_NEAR(a.H, a.G, 1e-15);
  // Just off it (a sine of 1e-6): both angles again.
  const Vector3d m = 2.0 * (gamma + Vector3d(0, 1e-6, 0));
  a = andoyer_variables(kBody, m.cwiseQuotient(kBody.inertia), gamma);
  EXPECT_TRUE(a.l && a.g);
}

TEST(Andoyer, AngleSidesAndTheirRates) {
  const DirectSystem sys(kBody);
  for (const Six& x : states(20)) {
    const Vector3d omega = x.head<3>().cwiseQuotient(kBody.inertia), gamma = x.tail<3>();
    const auto a = andoyer_variables(kBody, omega, gamma);
    DirectSystem::State s, ds;
    s << omega, gamma;
    sys.rhs(0.0, s, ds);
    for (auto which : {AndoyerAngle::l, AndoyerAngle::g}) {
      const double angle = which == AndoyerAngle::l ? *a.l : *a.g;
      const auto sides = andoyer_angle_sides(which, kBody, omega, gamma);
      const double r = std::hypot(sides.sine, sides.cosine);
      EXPECT_NEAR(sides.sine, r * std::sin(angle), 1e-12 * r);
      EXPECT_NEAR(sides.cosine, r * std::cos(angle), 1e-12 * r);
      const auto rate =
          andoyer_angle_sides_rate(which, kBody, omega, gamma, ds.head<3>(), ds.tail<3>());
      const double dt = 1e-6;
      const DirectSystem::State up = s + dt * ds, down = s - dt * ds;
      const auto su = andoyer_angle_sides(which, kBody, up.head<3>(), up.tail<3>());
      const auto sd = andoyer_angle_sides(which, kBody, down.head<3>(), down.tail<3>());
      EXPECT_NEAR(rate.sine, (su.sine - sd.sine) / (2 * dt), 1e-6 * (1 + std::abs(rate.sine)));
      EXPECT_NEAR(rate.cosine, (su.cosine - sd.cosine) / (2 * dt),
                  1e-6 * (1 + std::abs(rate.cosine)));
    }
  }
}

}  // namespace
}  // namespace epviz::physics
