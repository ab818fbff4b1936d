// Initial states on a level of (C1, C0) and the admissible minimum of C1.
// The oracles are written here: the integrals term by term from docs/math.md
// (1.4)-(1.5), the least kinetic energy on the plane I Omega . gamma = C0 by
// solving its Lagrange (KKT) system, and the closed forms derived below.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "helpers.hpp"
#include "physics/admissible.hpp"
#include "physics/cases.hpp"
#include "physics/level_set.hpp"

namespace epviz::physics {
namespace {

double energy_of(const Body& b, const Vector3d& w, const Vector3d& g) {
  const Vector3d& I = b.inertia;
  return 0.5 * (I[0] * w[0] * w[0] + I[1] * w[1] * w[1] + I[2] * w[2] * w[2]) +
         b.weight * (b.com[0] * g[0] + b.com[1] * g[1] + b.com[2] * g[2]);
}

double area_of(const Body& b, const Vector3d& w, const Vector3d& g) {
  const Vector3d& I = b.inertia;
  return I[0] * w[0] * g[0] + I[1] * w[1] * g[1] + I[2] * w[2] * g[2];
}

// min 1/2 w.I w subject to (I g).w = c0: stationarity I w = lambda I g and the
// constraint, solved as one linear system.
double kkt_floor(const Body& b, double c0, const Vector3d& g) {
  Eigen::Matrix4d a = Eigen::Matrix4d::Zero();
  const Vector3d n = b.inertia.cwiseProduct(g);
  a.topLeftCorner<3, 3>() = b.inertia.asDiagonal();
  a.block<3, 1>(0, 3) = -n;
  a.block<1, 3>(3, 0) = n.transpose();
  Eigen::Vector4d rhs(0, 0, 0, c0);
  const Eigen::Vector4d x = a.fullPivLu().solve(rhs);
  const Vector3d w = x.head<3>();
  return 0.5 * w.dot(b.inertia.cwiseProduct(w));
}

// The least C1 of a state with this gamma, by the oracle above.
double floor_at(const Body& b, double c0, const Vector3d& g) {
  return b.weight * b.com.dot(g) + kkt_floor(b, c0, g);
}

bool near(double value, double target, double tol = 1e-12) {
  return std::abs(value - target) <= tol * std::max(1.0, std::abs(target));
}

struct Named {
  const char* name;
  Body body;
};

std::vector<Named> preset_bodies() {
  return {{"generic", preset(Case::generic).body},
          {"kovalevskaya", preset(Case::kovalevskaya).body},
          {"lagrange", preset(Case::lagrange).body}};
}

TEST(LevelSet, EveryStateLiesOnTheLevel) {
  for (const auto& [name, body] : preset_bodies()) {
    for (const double c0 : {0.0, 0.8, -2.5}) {
      const double lowest = minimum_energy(body, c0).energy;
      // Above this bound every gamma has room: V <= P |r|, T_min <= C0^2 / (2 I_min).
      const double roomy = body.weight * body.com.norm() + c0 * c0 / (2 * body.inertia.minCoeff());
      for (const double above : {0.1, 1.0, 20.0}) {
        SCOPED_TRACE(std::string(name) + " C0 = " + std::to_string(c0) +
                     " C1 - min = " + std::to_string(above));
        const Level level{lowest + above, c0};
        const int n = 400;
        const LevelStates got = level_states(body, level, n);
        EXPECT_EQ(got.states.size() + got.rejected.size(), std::size_t(n));
        EXPECT_FALSE(got.states.empty());
        for (const auto& s : got.states) {
          EXPECT_NEAR(s.gamma.squaredNorm(), 1.0, 1e-12);
          EXPECT_TRUE(near(energy_of(body, s.omega, s.gamma), level.energy))
              << energy_of(body, s.omega, s.gamma) - level.energy;
          EXPECT_TRUE(near(area_of(body, s.omega, s.gamma), level.area))
              << area_of(body, s.omega, s.gamma) - level.area;
        }
        for (const auto& r : got.rejected) {
          ASSERT_EQ(r.why, Rejection::below_level);
          const double room = level.energy - body.weight * body.com.dot(r.gamma.normalized());
          const double need = kkt_floor(body, c0, r.gamma.normalized());
          EXPECT_LT(room, need);
          EXPECT_NEAR(r.shortfall, need - room, 1e-9 * std::max(1.0, need));
        }
        if (level.energy > roomy) {
          EXPECT_TRUE(got.rejected.empty());
        }
      }
    }
  }
}

TEST(LevelSet, BelowTheAdmissibleMinimumNoGammaHasAState) {
  for (const auto& [name, body] : preset_bodies()) {
    for (const double c0 : {0.0, 1.3}) {
      SCOPED_TRACE(name);
      const Level level{minimum_energy(body, c0).energy - 1e-3, c0};
      const LevelStates got = level_states(body, level, 500);
      EXPECT_TRUE(got.states.empty());
      ASSERT_EQ(got.rejected.size(), 500u);
      for (const auto& r : got.rejected) {
        EXPECT_EQ(r.why, Rejection::below_level);
        EXPECT_GT(r.shortfall, 0.0);
      }
    }
  }
}

TEST(LevelSet, StatesAreSpreadOverTheLevel) {
  const Body body = preset(Case::generic).body;
  const Level level{30.0, 1.1};
  const LevelStates got = level_states(body, level, 300);
  ASSERT_EQ(got.states.size(), 300u);
  Vector3d mean_gamma = Vector3d::Zero();
  double least_gap = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < got.states.size(); ++i) {
    mean_gamma += got.states[i].gamma / 300.0;
    for (std::size_t j = 0; j < i; ++j) {
      const double gap = (got.states[i].omega - got.states[j].omega).norm() +
                         (got.states[i].gamma - got.states[j].gamma).norm();
      least_gap = std::min(least_gap, gap);
    }
  }
  EXPECT_LT(mean_gamma.norm(), 0.02);  // the gammas cover the sphere
  EXPECT_GT(least_gap, 0.05);          // no two states coincide
}

TEST(LevelSet, RepeatedGammaGivesStatesAroundTheLevelsEllipse) {
  // At one gamma the Omegas of the level form an ellipse in the plane
  // I Omega . gamma = C0; repeats of that gamma must not all land on one point
  // (or on two opposite ones): their spread is two-dimensional.
  const Body body = preset(Case::generic).body;
  const Level level{6.0, -0.9};
  const std::vector<Vector3d> gammas(12, Vector3d(0.3, -0.5, 0.8).normalized());
  const LevelStates got = level_states(body, level, gammas);
  ASSERT_EQ(got.states.size(), 12u);
  Eigen::Matrix<double, 3, 12> dev;
  for (int i = 0; i < 12; ++i) {
    const auto& s = got.states[std::size_t(i)];
    EXPECT_TRUE(near(energy_of(body, s.omega, s.gamma), level.energy));
    EXPECT_TRUE(near(area_of(body, s.omega, s.gamma), level.area));
    dev.col(i) = s.omega;
    for (int j = 0; j < i; ++j)
      EXPECT_GT((s.omega - got.states[std::size_t(j)].omega).norm(), 0.05);
  }
  dev.colwise() -= dev.rowwise().mean();
  const Eigen::Vector3d sv = Eigen::JacobiSVD<Eigen::Matrix<double, 3, 12>>(dev).singularValues();
  EXPECT_GT(sv[1], 0.2 * sv[0]);
  EXPECT_LT(sv[2], 1e-9 * sv[0]);  // and it stays in the plane
}

TEST(LevelSet, FibonacciPointsAreUnitAndEvenlySpread) {
  EXPECT_TRUE(fibonacci_sphere(0).empty());
  const auto pts = fibonacci_sphere(800);
  ASSERT_EQ(pts.size(), 800u);
  int octant[8] = {};
  for (const auto& p : pts) {
    EXPECT_NEAR(p.norm(), 1.0, 1e-14);
    ++octant[(p.x() > 0) + 2 * (p.y() > 0) + 4 * (p.z() > 0)];
  }
  for (const int c : octant) EXPECT_NEAR(c, 100, 8);
}

TEST(LevelSet, GivenGammasAreNormalisedAndBadOnesReported) {
  const Body body = preset(Case::kovalevskaya).body;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Vector3d> gammas = {Vector3d(0, 0, 2), Vector3d::Zero(), Vector3d(nan, 0, 1),
                                        Vector3d(1, 1, 0)};
  const Level level{5.0, 0.5};
  const LevelStates got = level_states(body, level, gammas);
  ASSERT_EQ(got.states.size(), 2u);
  EXPECT_LT((got.states[0].gamma - Vector3d(0, 0, 1)).norm(), 1e-15);
  EXPECT_LT((got.states[1].gamma - Vector3d(1, 1, 0) / std::sqrt(2.0)).norm(), 1e-15);
  ASSERT_EQ(got.rejected.size(), 2u);
  EXPECT_EQ(got.rejected[0].why, Rejection::invalid_gamma);
  EXPECT_EQ(got.rejected[1].why, Rejection::invalid_gamma);
  EXPECT_THROW(level_states(body, Level{nan, 0.0}, 10), std::invalid_argument);
  EXPECT_THROW(minimum_energy(body, nan), std::invalid_argument);
}

TEST(LevelSet, AtTheMinimumTheStateIsTheSteadyOne) {
  // On the lowest level at its gamma the only Omega is C0 gamma / (gamma.I gamma).
  for (const auto& [name, body] : preset_bodies()) {
    SCOPED_TRACE(name);
    const double c0 = 1.7;
    const EnergyMinimum m = minimum_energy(body, c0);
    const LevelStates got = level_states(body, Level{m.energy, c0}, {m.gamma});
    ASSERT_EQ(got.states.size(), 1u);
    const Vector3d g = got.states[0].gamma;
    const Vector3d expect = c0 / g.dot(body.inertia.cwiseProduct(g)) * g;
    EXPECT_LT((got.states[0].omega - expect).norm(), 1e-6);
  }
}

// Levels just above the least energy at their area: the grid over the sphere
// meets no direction that carries a state, the caps about the minimiser do,
// and every state they give lies on the level (the integrals written out here).
TEST(LevelSet, LevelsJustAboveTheLeastEnergyAreReached) {
  struct Near {
    Case c;
    double area;
  };
  for (const auto& [c, area] : {Near{Case::kovalevskaya, 0.5},
                                Near{Case::lagrange, std::sqrt(24.5)}, Near{Case::generic, 1.3}}) {
    const Body& body = preset(c).body;
    const double least = minimum_energy(body, area).energy;
    for (double above : {1e-6, 1e-3, 3e-2}) {
      const Level level{least + above * std::max(1.0, std::abs(least)), area};
      const auto grid = level_states(body, level, 16).states.size();
      const auto near = level_states_about_minimum(body, level, 16);
      EXPECT_GE(near.states.size(), 16u) << case_name(c) << " " << above;
      if (above == 1e-6) {
        EXPECT_EQ(grid, 0u) << "the grid reaches it: the test shows nothing";
      }
      for (const auto& s : near.states) {
        EXPECT_NEAR(s.gamma.norm(), 1.0, 1e-14);
        EXPECT_NEAR(energy_of(body, s.omega, s.gamma), level.energy,
                    1e-11 * std::max(1.0, std::abs(level.energy)));
        EXPECT_NEAR(area_of(body, s.omega, s.gamma), area, 1e-11 * std::max(1.0, area));
      }
    }
    // Below the least energy no cap carries a state.
    const Level below{least - 1e-6 * std::max(1.0, std::abs(least)), area};
    EXPECT_TRUE(level_states_about_minimum(body, below, 16).states.empty()) << case_name(c);
  }
}

TEST(LevelSet, CapPointsLieInTheirCapEvenlyByArea) {
  const Vector3d centre = Vector3d(1.0, -2.0, 0.5).normalized();
  const double radius = 0.3;
  const auto points = fibonacci_cap(centre, radius, 400);
  ASSERT_EQ(points.size(), 400u);
  int inner = 0;  // in the inner cap of half the area
  const double half = std::acos(1.0 - 0.5 * (1.0 - std::cos(radius)));
  for (const auto& p : points) {
    EXPECT_NEAR(p.norm(), 1.0, 1e-14);
    const double angle = std::acos(std::clamp(p.dot(centre), -1.0, 1.0));
    EXPECT_LE(angle, radius + 1e-12);
    if (angle <= half) ++inner;
  }
  EXPECT_EQ(inner, 200);
}

TEST(AdmissibleMinimum, ZeroAreaIsTheLeastPotential) {
  // C0 = 0: T_min = 0 and P r.gamma is least at gamma = -r/|r|.
  test::Random rng;
  std::vector<Body> bodies;
  for (const auto& nb : preset_bodies()) bodies.push_back(nb.body);
  for (int i = 0; i < 5; ++i) bodies.push_back(test::random_body(rng));
  for (const Body& body : bodies) {
    const EnergyMinimum m = minimum_energy(body, 0.0);
    EXPECT_TRUE(near(m.energy, -body.weight * body.com.norm()));
    EXPECT_LT((m.gamma + body.com.normalized()).norm(), 1e-7);
  }
}

TEST(AdmissibleMinimum, BothTermsLeastTogetherWhenHangingOnTheLargestAxis) {
  // V >= -P|r| and T_min >= C0^2 / (2 I_max), with equality in both at
  // gamma = -r/|r| when r lies on the axis of the largest moment: an oblate
  // Lagrange top hanging (c0 < 0 here, so gamma = +e3), and the torque-free body.
  const Body oblate{Vector3d(2, 2, 3), Vector3d(0, 0, -0.7), 1.5};
  const Body free{Vector3d(1, 2, 3), Vector3d::Zero(), 1.0};
  for (const double c0 : {0.4, -1.5, 3.0}) {
    const EnergyMinimum a = minimum_energy(oblate, c0);
    EXPECT_TRUE(near(a.energy, -1.05 + c0 * c0 / 6.0));
    EXPECT_LT((a.gamma - Vector3d(0, 0, 1)).norm(), 1e-7);
    const EnergyMinimum b = minimum_energy(free, c0);
    EXPECT_TRUE(near(b.energy, c0 * c0 / 6.0));
    EXPECT_NEAR(std::abs(b.gamma.z()), 1.0, 1e-12);
  }
}

TEST(AdmissibleMinimum, ProlateLagrangeTopLeansOver) {
  // Preset Lagrange top: I = (2, 2, 1), r = (0, 0, 1), P = 4. With z = gamma3,
  // E(z) = 4 z + C0^2 / (2 (2 - z^2)) and E'(z) = f(z) / (2 - z^2)^2 where
  // f(z) = 4 (2 - z^2)^2 + C0^2 z. Choosing C0^2 = 24.5 puts the root of f at
  // z = -1/2; f' = -16 z (2 - z^2) + 24.5 > 0 on [-1, 0] and f > 0 on [0, 1],
  // so it is the only one and E is least there: E(-1/2) = -2 + 24.5 / 3.5 = 5,
  // below the poles (8.25, 16.25).
  const Body body = preset(Case::lagrange).body;
  ASSERT_EQ(body.inertia, Vector3d(2, 2, 1));
  ASSERT_EQ(body.com, Vector3d(0, 0, 1));
  ASSERT_EQ(body.weight, 4.0);
  const EnergyMinimum m = minimum_energy(body, std::sqrt(24.5));
  EXPECT_TRUE(near(m.energy, 5.0));
  EXPECT_NEAR(m.gamma.z(), -0.5, 1e-7);
}

TEST(AdmissibleMinimum, GenericBodyAgainstBoundsAndSampling) {
  test::Random rng;
  for (int k = 0; k < 4; ++k) {
    const Body body = k == 0 ? preset(Case::generic).body : test::random_body(rng);
    const double c0 = rng.uniform(-3.0, 3.0);
    const EnergyMinimum m = minimum_energy(body, c0);
    EXPECT_NEAR(m.gamma.norm(), 1.0, 1e-14);
    EXPECT_TRUE(near(floor_at(body, c0, m.gamma), m.energy));  // attained
    EXPECT_GE(m.energy, -body.weight * body.com.norm() + c0 * c0 / (2 * body.inertia.maxCoeff()));
    double sampled = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 20000; ++i) {
      const double f = floor_at(body, c0, rng.unit());
      EXPECT_GE(f, m.energy - 1e-12 * std::max(1.0, std::abs(m.energy)));
      sampled = std::min(sampled, f);
    }
    EXPECT_LT(sampled - m.energy, 1e-2);
  }
}

}  // namespace
}  // namespace epviz::physics
