// The chaotic share of a level (sweep/level_point.hpp) against what is known
// of the bodies, not against the code's own output: the Kovalevskaya top is
// integrable, so no orbit of it is chaotic (share 0) even where one has a
// large FTLE, its planar pendulum motion at C0 = 0, hyperbolic above
// C1 of about 0.3 (docs/cluster.md); the generic body has chaotic levels.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "physics/cases.hpp"
#include "sim/run_spec.hpp"
#include "sweep/atlas_labels.hpp"
#include "sweep/level_point.hpp"

namespace epviz::test {
namespace {

// The shipped maps' runs (render_jobs/energy_momentum_*.sweep.json): T = 100,
// dop853 at tol 1e-12, FTLE window 1 and separation 1e-8.
sim::RunSpec map_run(physics::Case c) {
  sim::RunSpec run = sim::preset_run(c, sim::Method::dop853, sim::Formulation::direct, 100.0, 1);
  run.tol = 1e-12;
  return run;
}
const sweep::FtleSettings kFtle{1e-8, 1.0};

TEST(ChaoticShare, AnIntegrableTopHasNoChaosEvenOnItsHyperbolicPendulum) {
  const auto run = map_run(physics::Case::kovalevskaya);
  // C0 = 0, C1 = 1.5: the generator's first orbit is the planar pendulum.
  const auto m = sweep::level_metrics(run, {1.5, 0.0}, 8, kFtle);
  ASSERT_TRUE(m.admissible);
  ASSERT_EQ(m.lost, 0);
  // The FTLE sees the hyperbolic orbit ...
  ASSERT_TRUE(m.largest_ftle);
  EXPECT_GT(*m.largest_ftle, sweep::kChaoticFtle);
  // ... which keeps K, as every orbit of the top must: not chaos.
  ASSERT_TRUE(m.extra_integral_range);
  EXPECT_LT(*m.extra_integral_range, sweep::kKeptIntegral);
  EXPECT_EQ(m.chaotic, 0);
  EXPECT_GE(m.hyperbolic, 1);
  EXPECT_EQ(m.undecided, 0);
  ASSERT_TRUE(m.chaotic_share);
  EXPECT_EQ(*m.chaotic_share, 0.0);
}

// A run too coarse to keep K cannot say: its orbits above the threshold are
// undecided and left out of the share, never called chaotic.
TEST(ChaoticShare, AnIntegralNotKeptLeavesTheOrbitUndecided) {
  auto run = map_run(physics::Case::kovalevskaya);
  run.method = sim::Method::rk4;
  run.step = 0.25;  // far too coarse for T = 100: K drifts by much more than 1e-6
  const auto m = sweep::level_metrics(run, {1.5, 0.0}, 8, kFtle);
  ASSERT_TRUE(m.admissible);
  EXPECT_EQ(m.chaotic, 0);
  ASSERT_TRUE(m.extra_integral_range);
  ASSERT_GT(*m.extra_integral_range, sweep::kKeptIntegral) << "the run keeps K after all";
  EXPECT_GE(m.undecided, 1);
  if (m.chaotic_share) {
    EXPECT_EQ(*m.chaotic_share, 0.0);
  }
}

TEST(ChaoticShare, TheGenericBodyStillShowsChaos) {
  const auto run = map_run(physics::Case::generic);
  const auto m = sweep::level_metrics(run, {1.5, 0.5}, 8, kFtle);
  ASSERT_TRUE(m.admissible);
  EXPECT_FALSE(m.extra_integral_range) << "the generic body has no fourth integral";
  EXPECT_GT(m.chaotic, 0);
  ASSERT_TRUE(m.chaotic_share);
  EXPECT_GT(*m.chaotic_share, 0.0);
  EXPECT_EQ(m.hyperbolic + m.undecided, 0);
}

// The map says what its zeros hide: the orbits above the threshold that it
// did not count as chaotic, by kind.
TEST(ChaoticShare, TheCaptionCountsHyperbolicAndUndecidedOrbits) {
  const nlohmann::json a = {{"case", "kovalevskaya"},
                            {"hyperbolic_orbits", 2},
                            {"undecided_orbits", 0}},
                       b = {{"case", "kovalevskaya"},
                            {"hyperbolic_orbits", 1},
                            {"undecided_orbits", 1}};
  const std::string caption = sweep::atlas_caption({&a, &b}, "chaotic_share", std::nullopt);
  EXPECT_NE(caption.find("3 orbits with FTLE > 0.1 kept K: hyperbolic, not chaotic"),
            std::string::npos)
      << caption;
  EXPECT_NE(caption.find("1 orbit with FTLE > 0.1 undecided"), std::string::npos) << caption;
  const nlohmann::json plain = {
      {"case", "generic"}, {"hyperbolic_orbits", 0}, {"undecided_orbits", 0}};
  EXPECT_EQ(sweep::atlas_caption({&plain}, "chaotic_share", std::nullopt).find("hyperbolic"),
            std::string::npos);
}

}  // namespace
}  // namespace epviz::test
