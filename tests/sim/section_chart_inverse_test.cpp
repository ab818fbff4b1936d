// The inverse of a section panel's chart, against the forward chart as its
// oracle: random states on a surface are plotted, and the states found at
// their points must include them and satisfy every condition of the chart
// (the surface, the coords, the level's C0 and C1, |gamma| = 1, the direction
// of crossing by the direct equations' own right-hand side).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "physics/cases.hpp"
#include "physics/direct.hpp"
#include "physics/invariants.hpp"
#include "sim/section_chart_inverse.hpp"

namespace epviz {
namespace {

using sim::StateComponent;
using Coords = std::array<StateComponent, 2>;

double rate_of(const physics::Body& body, const physics::InitialState& s, StateComponent f) {
  physics::DirectSystem sys(body);
  physics::DirectSystem::State x, dx;
  x << s.omega, s.gamma;
  sys.rhs(0.0, x, dx);
  return dx[Eigen::Index(f)];
}

physics::Level level_of(const physics::Body& body, const physics::InitialState& s) {
  const auto inv = physics::invariants(body, physics::Case::custom, s.omega, s.gamma);
  return {inv.energy, inv.area};
}

// Every condition a state of the preimage must meet.
void expect_in_chart(const physics::Body& body, const physics::Level& level,
                     const sim::SectionSurface& surface, const Coords& coords, double x, double y,
                     const physics::InitialState& s) {
  const double scale = std::max(1.0, std::abs(level.energy) + std::abs(level.area));
  const auto inv = physics::invariants(body, physics::Case::custom, s.omega, s.gamma);
  EXPECT_NEAR(inv.energy, level.energy, 1e-12 * scale);
  EXPECT_NEAR(inv.area, level.area, 1e-12 * scale);
  EXPECT_NEAR(s.gamma.norm(), 1.0, 1e-12);
  EXPECT_NEAR(sim::value_of(surface.function, s.omega, s.gamma), surface.value, 1e-12);
  EXPECT_NEAR(sim::value_of(coords[0], s.omega, s.gamma), x, 1e-12 * std::max(1.0, std::abs(x)));
  EXPECT_NEAR(sim::value_of(coords[1], s.omega, s.gamma), y, 1e-12 * std::max(1.0, std::abs(y)));
  const double rate = rate_of(body, s, surface.function);
  if (surface.direction == sim::CrossingDirection::upward) {
    EXPECT_GT(rate, 0.0);
  }
  if (surface.direction == sim::CrossingDirection::downward) {
    EXPECT_LT(rate, 0.0);
  }
}

struct Chart {
  sim::SectionSurface surface;
  Coords coords;
};

class InverseChart : public ::testing::TestWithParam<Chart> {};

TEST_P(InverseChart, FindsRandomStatesOfTheSurfaceFromTheirPoints) {
  const Chart chart = GetParam();
  const auto sheet = sim::chart_sheet_component(chart.surface, chart.coords);
  ASSERT_TRUE(sheet);
  // An asymmetric body, so that no symmetry makes a wrong root right.
  physics::Body body{{1.3, 2.1, 2.9}, {0.4, -0.25, 0.7}, 1.7};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI), rate(-2.0, 2.0);
  const int k = int(chart.surface.function) - 3;
  int checked = 0;
  for (int trial = 0; trial < 400; ++trial) {
    physics::InitialState s;
    const double c = chart.surface.value, rho = std::sqrt(1.0 - c * c), phi = angle(rng);
    s.gamma[k] = c;
    s.gamma[(k + 1) % 3] = rho * std::cos(phi);
    s.gamma[(k + 2) % 3] = rho * std::sin(phi);
    s.omega = {rate(rng), rate(rng), rate(rng)};
    const double r = rate_of(body, s, chart.surface.function);
    const bool asked =
        chart.surface.direction == sim::CrossingDirection::upward ? r > 0.0 : r < 0.0;
    const physics::Level level = level_of(body, s);
    const double x = sim::value_of(chart.coords[0], s.omega, s.gamma);
    const double y = sim::value_of(chart.coords[1], s.omega, s.gamma);
    const int sign = sim::value_of(*sheet, s.omega, s.gamma) > 0.0 ? 1 : -1;
    const auto pre = sim::section_states_at(body, level, chart.surface, chart.coords, x, y, sign);
    bool has_it = false;
    for (const auto& p : pre.states) {
      expect_in_chart(body, level, chart.surface, chart.coords, x, y, p);
      EXPECT_EQ(sim::value_of(*sheet, p.omega, p.gamma) > 0.0 ? 1 : -1, sign);
      has_it |= (p.omega - s.omega).norm() < 1e-9 && (p.gamma - s.gamma).norm() < 1e-12;
    }
    // The state plotted is found where it crosses as asked, and only there.
    EXPECT_EQ(has_it, asked) << "trial " << trial;
    if (asked) {
      EXPECT_TRUE(pre.why_none.empty());
    }
    checked += asked;
  }
  EXPECT_GT(checked, 100);
}

INSTANTIATE_TEST_SUITE_P(
    Charts, InverseChart,
    ::testing::Values(Chart{{StateComponent::gamma3, 0.0, sim::CrossingDirection::upward},
                            {StateComponent::gamma1, StateComponent::omega3}},
                      Chart{{StateComponent::gamma3, 0.3, sim::CrossingDirection::downward},
                            {StateComponent::omega3, StateComponent::gamma2}},
                      Chart{{StateComponent::gamma1, -0.5, sim::CrossingDirection::upward},
                            {StateComponent::gamma3, StateComponent::omega1}}));

// The shipped chart on the Kovalevskaya top (I1 = I2): each sheet has exactly
// one upward state at an admissible point, the two Omega on its line being
// on either side of the fold's direction.
TEST(InverseChartKovalevskaya, OneUpwardStateASheet) {
  const auto preset = physics::preset(physics::Case::kovalevskaya);
  const physics::Body body = preset.body;
  const physics::InitialState start = preset.initial;
  const physics::Level level = level_of(body, start);
  const sim::SectionSurface surface;  // gamma3 = 0, upward
  const Coords coords{StateComponent::gamma1, StateComponent::omega3};
  const auto both = sim::section_states_at(body, level, surface, coords, 0.2, 0.1, 0);
  ASSERT_EQ(both.states.size(), 2u) << both.why_none;
  EXPECT_NE(both.states[0].gamma.y() > 0.0, both.states[1].gamma.y() > 0.0);
  for (const auto& s : both.states) expect_in_chart(body, level, surface, coords, 0.2, 0.1, s);
  const auto upper = sim::section_states_at(body, level, surface, coords, 0.2, 0.1, +1);
  ASSERT_EQ(upper.states.size(), 1u);
  EXPECT_GT(upper.states[0].gamma.y(), 0.0);
}

TEST(InverseChartRefuses, PointsWithNoStateSayWhy) {
  const auto preset = physics::preset(physics::Case::kovalevskaya);
  const physics::Body body = preset.body;
  const physics::Level level = level_of(body, preset.initial);
  const sim::SectionSurface surface;
  const Coords coords{StateComponent::gamma1, StateComponent::omega3};
  // |gamma1| > 1 on gamma3 = 0: no unit gamma.
  auto none = sim::section_states_at(body, level, surface, coords, 1.2, 0.0);
  EXPECT_TRUE(none.states.empty());
  EXPECT_NE(none.why_none.find("no unit"), std::string::npos) << none.why_none;
  // Omega3 with more kinetic energy than the level has: 1/2 I3 Omega3^2 > C1 + P|r|.
  const double w3 =
      2.0 * std::sqrt(2.0 * (level.energy + body.weight * body.com.norm()) / body.inertia.z());
  none = sim::section_states_at(body, level, surface, coords, 0.0, w3);
  EXPECT_TRUE(none.states.empty());
  EXPECT_NE(none.why_none.find("lacks"), std::string::npos) << none.why_none;
}

TEST(InverseChartRefuses, ChartsItCannotInvert) {
  const sim::SectionSurface surface;  // gamma3 = 0
  EXPECT_FALSE(
      sim::chart_sheet_component(surface, {StateComponent::omega1, StateComponent::omega2}));
  EXPECT_FALSE(
      sim::chart_sheet_component(surface, {StateComponent::gamma1, StateComponent::omega1}));
  EXPECT_FALSE(sim::chart_sheet_component({StateComponent::omega3, 0.0, {}},
                                          {StateComponent::gamma1, StateComponent::gamma2}));
  EXPECT_FALSE(sim::chart_sheet_component({StateComponent::gamma3, 1.0, {}},
                                          {StateComponent::gamma1, StateComponent::omega3}));
  EXPECT_EQ(sim::chart_sheet_component(surface, {StateComponent::gamma1, StateComponent::omega3}),
            StateComponent::gamma2);
  EXPECT_THROW((void)sim::section_states_at(physics::Body{}, {}, surface,
                                            {StateComponent::omega1, StateComponent::omega2}, 0, 0),
               std::invalid_argument);
}

}  // namespace
}  // namespace epviz
