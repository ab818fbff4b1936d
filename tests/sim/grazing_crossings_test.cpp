// Grazing passages: an orbit that passes through the section surface and
// back within one step of the integrator. A sign test of the step's ends sees
// neither crossing; the section must find both, as a far finer integration
// by another method does, on the scalar path and the batch path alike.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "physics/cases.hpp"
#include "physics/direct.hpp"
#include "sim/section.hpp"
#include "sim/trajectory.hpp"

namespace epviz {
namespace {

// A Lagrange top started at a turning point of gamma3 that lies 1e-4 past
// the surface gamma3 = 0: gamma2 = Omega2 = 0 makes gamma3' = 0, and the
// sign of gamma3'' picks the side, so that every period gamma3 dips 1e-4
// through the surface and comes back within about 0.03 time units.
sim::RunSpec grazing_lagrange(sim::Method method) {
  const auto& preset = physics::preset(physics::Case::lagrange);
  const physics::DirectSystem sys(preset.body);
  const auto at = [&](double u) {
    physics::InitialState s;
    s.omega = {preset.initial.omega.x(), 0.0, preset.initial.omega.z()};
    s.gamma = {std::sqrt(1.0 - u * u), 0.0, u};
    return s;
  };
  // gamma3'' at u = 0, from gamma3' = gamma1 Omega2 - gamma2 Omega1.
  physics::DirectSystem::State x, dx;
  x << at(0.0).omega, at(0.0).gamma;
  sys.rhs(0.0, x, dx);
  const double curvature = x[3] * dx[1] - dx[4] * x[0];
  const double u0 = curvature < 0.0 ? 1e-4 : -1e-4;  // a maximum above, or a minimum below
  sim::RunSpec run = sim::body_run(physics::Case::lagrange, preset.body, at(u0), method,
                                   sim::Formulation::direct, 60.0, 1);
  run.tol = 1e-8;
  run.step = 1e-4;
  return run;
}

sim::SectionSurface gamma3_zero(sim::CrossingDirection d) {
  sim::SectionSurface s;
  s.function = sim::StateComponent::gamma3;
  s.value = 0.0;
  s.direction = d;
  return s;
}

// Sign changes of gamma3 between the ends of consecutive steps of `run`:
// what a search that looks at the step ends alone would find.
int end_sign_changes(const sim::RunSpec& run) {
  auto trajectory = sim::Trajectory::start(run);
  int changes = 0;
  double previous = trajectory->initial().gamma.z();
  trajectory->observe_steps([&](const sim::Sample& s) {
    if ((s.gamma.z() < 0.0) != (previous < 0.0)) ++changes;
    previous = s.gamma.z();
  });
  trajectory->next();
  return changes;
}

TEST(GrazingCrossings, EveryPassageThroughTheSurfaceIsFoundAsAFineRk4FindsIt) {
  const auto dop = grazing_lagrange(sim::Method::dop853);
  const auto fine = grazing_lagrange(sim::Method::rk4);  // h = 1e-4, far below a passage
  for (auto direction : {sim::CrossingDirection::both, sim::CrossingDirection::upward,
                         sim::CrossingDirection::downward}) {
    const auto surface = gamma3_zero(direction);
    const auto found = sim::section_crossings(dop, surface, 100000);
    const auto oracle = sim::section_crossings(fine, surface, 100000);
    ASSERT_GE(oracle.size(), 10u) << "the orbit must pass the surface many times";
    ASSERT_EQ(found.size(), oracle.size()) << "direction " << sim::name(direction);
    for (std::size_t i = 0; i < found.size(); ++i) {
      // Near a turning point the crossing time is sensitive (g' is about
      // 0.01 there, so DOP853's 1e-8 in the state is about 1e-6 in time);
      // the two crossings of a passage are 0.03 apart.
      EXPECT_NEAR(found[i].t, oracle[i].t, 1e-4) << "crossing " << i + 1;
      EXPECT_NEAR(found[i].gamma.z(), 0.0, 1e-11);
      EXPECT_EQ(found[i].number, int(i) + 1);
    }
    // The crossings come in pairs, 0.03 apart: back and through again (the
    // orbit starts at the turning point, so its first passage is half done).
    if (direction == sim::CrossingDirection::both) {
      EXPECT_LT(found[0].t, 0.05);
      for (std::size_t i = 1; i + 1 < found.size(); i += 2)
        EXPECT_LT(found[i + 1].t - found[i].t, 0.05) << "pair " << i / 2;
    }
  }
  // The case is a grazing one: DOP853's steps straddle most passages, so a
  // test of the step ends alone would lose them.
  const auto both = sim::section_crossings(dop, gamma3_zero(sim::CrossingDirection::both), 100000);
  EXPECT_LT(end_sign_changes(dop), int(both.size()) / 2)
      << "too few grazing passages to test anything";
}

TEST(GrazingCrossings, TheBatchPathFindsTheScalarPathsCrossingsBitwise) {
  auto a = grazing_lagrange(sim::Method::dop853);
  auto b = a;
  b.initial.omega.x() *= 1.001;  // a second lane, grazing a little differently
  const auto surface = gamma3_zero(sim::CrossingDirection::both);
  const auto batched = sim::section_crossings_batched({a, b}, surface, 100000, 1);
  ASSERT_EQ(batched.size(), 2u);
  for (const auto& [run, lane] : {std::pair{a, batched[0]}, std::pair{b, batched[1]}}) {
    ASSERT_FALSE(lane.failure);
    const auto scalar = sim::section_crossings(run, surface, 100000);
    ASSERT_EQ(lane.crossings.size(), scalar.size());
    for (std::size_t i = 0; i < scalar.size(); ++i) {
      EXPECT_EQ(lane.crossings[i].t, scalar[i].t) << "crossing " << i + 1;
      EXPECT_EQ(lane.crossings[i].gamma, scalar[i].gamma) << "crossing " << i + 1;
      EXPECT_EQ(lane.crossings[i].omega, scalar[i].omega) << "crossing " << i + 1;
    }
  }
}

TEST(GrazingCrossings, AnOrbitThatTurnsShortOfTheSurfaceHasNoCrossing) {
  auto run = grazing_lagrange(sim::Method::dop853);
  // The same turning point on the near side of the surface.
  run.initial.gamma.z() = -run.initial.gamma.z();
  const auto crossings =
      sim::section_crossings(run, gamma3_zero(sim::CrossingDirection::both), 100000);
  const auto fine = [&] {
    auto r = run;
    r.method = sim::Method::rk4;
    return sim::section_crossings(r, gamma3_zero(sim::CrossingDirection::both), 100000);
  }();
  EXPECT_EQ(crossings.size(), fine.size());
}

}  // namespace
}  // namespace epviz
