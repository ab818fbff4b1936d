// Stability studies push methods into their failure regimes: the failure must
// be detected and reported (time, method, reason) and the robust method must
// succeed on the same case.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/study_bench.hpp"
#include "sim/study_reference.hpp"

namespace epviz {
namespace {

const sim::StudyRow& row_with(const std::vector<sim::StudyRow>& rows, const std::string& key,
                              const std::string& value) {
  for (const auto& r : rows)
    if (r.text_of(key) == value) return r;
  throw std::runtime_error("no row with " + key + " = " + value);
}

TEST(StudyStability, RiccatiWithoutChartSwitchFailsAtThePassage) {
  sim::StudyOptions o;
  o.quick = true;
  o.repeats = 1;
  const auto rows = sim::stability_pole(o);
  const auto& bad = row_with(rows, "variant", "riccati-no-switch");
  EXPECT_EQ(bad.text_of("status"), "failed");
  EXPECT_EQ(bad.text_of("failure_method"), "dop853");
  EXPECT_FALSE(bad.text_of("failure_reason")->empty());
  EXPECT_NEAR(*bad.number("failure_t"), 2.0, 0.5);  // the passage is at t = 2
  EXPECT_TRUE(std::isnan(*bad.number("error")));
  for (const char* ok : {"riccati+chart-switch", "spinor", "direct"}) {
    const auto& r = row_with(rows, "variant", ok);
    EXPECT_EQ(r.text_of("status"), "ok") << ok << ": " << *r.text_of("failure_reason");
    EXPECT_LT(*r.number("error"), 1e-6) << ok;
  }
  EXPECT_GE(*row_with(rows, "variant", "riccati+chart-switch").number("chart_switches"), 1.0);
}

TEST(StudyStability, Rk4WithTooLargeStepIsReportedAndRobustMethodSucceeds) {
  const auto c = physics::Case::kovalevskaya;
  const auto& p = physics::preset(c);
  const double t_end = 20.0, period = sim::fastest_period(p.initial);
  const auto ref = sim::compute_reference(p.body, p.initial, t_end, 1, sim::reference_step(p.initial));
  const auto big = sim::check_fixed_step(c, sim::Method::rk4, 2.0 * period, t_end, ref.samples.back());
  EXPECT_FALSE(big.ok);
  EXPECT_EQ(big.reason.rfind("blew up", 0), 0u) << big.reason;
  const auto small = sim::check_fixed_step(c, sim::Method::rk4, period / 100.0, t_end, ref.samples.back());
  EXPECT_TRUE(small.ok) << small.reason;
  const auto robust = sim::check_fixed_step(c, sim::Method::gauss6, period / 20.0, t_end, ref.samples.back());
  EXPECT_TRUE(robust.ok) << robust.reason;
  // And DOP853 with step control goes through the same case.
  auto spec = sim::preset_run(c, sim::Method::dop853, sim::Formulation::direct, t_end, 1);
  spec.tol = 1e-10;
  const auto r = sim::simulate(spec);
  ASSERT_FALSE(r.failure);
  EXPECT_LT(sim::state_error(r.samples.back(), ref.samples.back()), 1e-7);
}

TEST(StudyStability, LargestStepIsBracketed) {
  sim::StudyOptions o;
  o.quick = true;
  o.methods = {sim::Method::rk4};
  const auto rows = sim::stability_max_step(o);
  ASSERT_EQ(rows.size(), 2u);  // kovalevskaya and lagrange
  for (const auto& r : rows) {
    const double h = *r.number("max_step"), bad = *r.number("failing_step");
    ASSERT_TRUE(std::isfinite(h)) << *r.text_of("case");
    EXPECT_GT(bad, h);
    EXPECT_LT(bad, 1.1 * h);
    EXPECT_FALSE(r.text_of("failure_reason")->empty());
    EXPECT_GT(*r.number("max_step_over_period"), 0.01);
  }
}

TEST(StudyStability, SeparatrixAndChaosRowsAreMeasured) {
  sim::StudyOptions o;
  o.quick = true;
  o.methods = {sim::Method::dop853};
  const auto flips = sim::stability_separatrix(o);
  ASSERT_EQ(flips.size(), 3u);
  // Tighter tolerance, smaller flip-time error.
  EXPECT_LT(*flips.back().number("flip_time_error"), *flips.front().number("flip_time_error") + 1e-12);
  EXPECT_LT(*flips.back().number("flip_time_error"), 1e-3);
  const auto chaos = sim::stability_chaos(o);
  ASSERT_EQ(chaos.size(), 3u);
  const double loose = *chaos.front().number("separation_time");
  const double tight = chaos.back().number("separation_time").value();
  EXPECT_TRUE(std::isnan(tight) || tight >= loose);
}

}  // namespace
}  // namespace epviz
