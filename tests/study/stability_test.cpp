// Stability studies push methods into their failure regimes: the failure must
// be detected and reported (time, method, reason) and the robust method must
// succeed on the same case.
#include <gtest/gtest.h>

#include <cmath>

#include "study/pole_passage.hpp"
#include "study/quick_options.hpp"
#include "study/reference.hpp"
#include "study/stability.hpp"

namespace epviz {
namespace {

const study::PolePassageRow& variant(const std::vector<study::PolePassageRow>& rows,
                                     const std::string& name) {
  for (const auto& r : rows)
    if (r.variant == name) return r;
  throw std::runtime_error("no row with variant " + name);
}

TEST(StudyStability, RiccatiWithoutChartSwitchFailsAtThePassage) {
  const auto rows = study::stability_pole(testing::quick_options());
  const auto& bad = variant(rows, "riccati-no-switch");
  EXPECT_FALSE(bad.run.ok);
  EXPECT_EQ(bad.failure_method, "dop853");
  EXPECT_FALSE(bad.run.failure_reason.empty());
  EXPECT_NEAR(bad.run.failure_t, 2.0, 0.5);  // the passage is at t = 2
  EXPECT_TRUE(std::isnan(bad.error));
  for (const char* ok : {"riccati+chart-switch", "spinor", "direct"}) {
    const auto& r = variant(rows, ok);
    EXPECT_TRUE(r.run.ok) << ok << ": " << r.run.failure_reason;
    EXPECT_LT(r.error, 1e-6) << ok;
  }
  EXPECT_GE(variant(rows, "riccati+chart-switch").chart_switches, 1);
}

TEST(StudyStability, Rk4WithTooLargeStepIsReportedAndRobustMethodSucceeds) {
  const auto c = physics::Case::kovalevskaya;
  const auto& p = physics::preset(c);
  const double t_end = 20.0, period = study::fastest_period(p.initial);
  const auto ref =
      study::compute_reference(p.body, p.initial, t_end, 1, study::reference_step(p.initial));
  const auto big =
      study::check_fixed_step(c, sim::Method::rk4, 2.0 * period, t_end, ref.samples.back());
  EXPECT_FALSE(big.ok);
  EXPECT_EQ(big.reason.rfind("blew up", 0), 0u) << big.reason;
  const auto small =
      study::check_fixed_step(c, sim::Method::rk4, period / 100.0, t_end, ref.samples.back());
  EXPECT_TRUE(small.ok) << small.reason;
  const auto robust =
      study::check_fixed_step(c, sim::Method::gauss6, period / 20.0, t_end, ref.samples.back());
  EXPECT_TRUE(robust.ok) << robust.reason;
  // And DOP853 with step control goes through the same case.
  auto spec = sim::preset_run(c, sim::Method::dop853, sim::Formulation::direct, t_end, 1);
  spec.tol = 1e-10;
  const auto r = sim::simulate(spec);
  ASSERT_FALSE(r.failure);
  EXPECT_LT(study::state_error(r.samples.back(), ref.samples.back()), 1e-7);
}

TEST(StudyStability, LargestStepIsBracketed) {
  const auto rows = study::stability_max_step(testing::quick_options({sim::Method::rk4}));
  ASSERT_EQ(rows.size(), 2u);  // kovalevskaya and lagrange
  for (const auto& r : rows) {
    const double h = r.max_step, bad = r.failing_step;
    ASSERT_TRUE(std::isfinite(h)) << r.case_name;
    EXPECT_GT(bad, h);
    EXPECT_LT(bad, 1.1 * h);
    EXPECT_FALSE(r.failure_reason.empty());
    EXPECT_GT(r.max_step_over_period, 0.01);
  }
}

TEST(StudyStability, SeparatrixAndChaosRowsAreMeasured) {
  const auto o = testing::quick_options({sim::Method::dop853});
  const auto flips = study::stability_separatrix(o);
  ASSERT_EQ(flips.size(), 3u);
  // Tighter tolerance, smaller flip-time error.
  EXPECT_LT(flips.back().flip_time_error, flips.front().flip_time_error + 1e-12);
  EXPECT_LT(flips.back().flip_time_error, 1e-3);
  const auto chaos = study::stability_chaos(o);
  ASSERT_EQ(chaos.size(), 3u);
  const double loose = chaos.front().separation_time;
  const double tight = chaos.back().separation_time;
  EXPECT_TRUE(std::isnan(tight) || tight >= loose);
}

}  // namespace
}  // namespace epviz
