// The invariant-cost study finds, per method, the cheapest setting that keeps
// C1 and the fourth integral within the target; the chaos study's initial
// state is strongly chaotic.
#include <gtest/gtest.h>

#include <cmath>

#include "study/invariant_cost.hpp"
#include "study/quick_options.hpp"
#include "study/reference.hpp"
#include "study/stability.hpp"

namespace epviz {
namespace {

TEST(StudyInvariantCost, ReachedRowsMeetTheTargetAndExactSplit4ReachesIt) {
  const auto o = testing::quick_options({sim::Method::rk4, sim::Method::exact_split4});
  const double t_end = 100.0, target = 1e-8;
  const auto rows = study::invariant_cost_study(o, t_end, target);
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& r : rows) {
    EXPECT_EQ(r.run.case_name, "kovalevskaya");
    EXPECT_EQ(r.run.t_end, t_end);
    EXPECT_EQ(r.target, target);
    EXPECT_GT(r.run.cost(), 0);
    EXPECT_GT(r.run.rhs_evals + r.run.flow_evals, 0);
    if (r.reached) {
      EXPECT_LT(r.drift_C1, target) << r.run.method;
      EXPECT_LT(r.drift_extra, target) << r.run.method;
      EXPECT_TRUE(r.run.ok);
    }
  }
  const auto& split4 = rows[1];
  ASSERT_EQ(split4.run.method, "exact-split4");
  EXPECT_TRUE(split4.reached);
  EXPECT_LT(split4.drift_C1, target);
}

TEST(StudyInvariantCost, ChaosStateSeparatesFastAndRanksTolerances) {
  const auto& g = physics::preset(physics::Case::generic);
  const auto s = study::chaos_initial_state();
  const double t_end = 60.0;  // the quick chaos study's span
  sim::RunSpec a;
  a.body = g.body;
  a.initial = s;
  a.method = sim::Method::dop853;
  a.tol = 1e-13;
  a.t_end = t_end;
  a.samples = 1200;
  const auto ra = sim::simulate(a);
  for (int d = 0; d < 3; ++d) {
    auto b = a;
    b.initial.omega[d] += 1e-9;
    const auto rb = sim::simulate(b);
    double sep = NAN;
    for (std::size_t i = 0; i < ra.samples.size(); ++i)
      if (study::state_error(ra.samples[i], rb.samples[i]) > 1e-3) {
        sep = ra.samples[i].t;
        break;
      }
    EXPECT_LT(sep, 40.0) << "direction " << d;  // NaN (never separated) fails too
  }
  // The preset state, by contrast, stays within 1e-3 over the same span.
  a.initial = g.initial;
  auto b = a;
  b.initial.omega[0] += 1e-9;
  const auto pa = sim::simulate(a), pb = sim::simulate(b);
  EXPECT_LT(study::state_error(pa.samples.back(), pb.samples.back()), 1e-3);

  // dop853 separates later at tighter tolerance, and the loosest separates within the span.
  const auto o = testing::quick_options({sim::Method::dop853});
  const auto chaos = study::stability_chaos(o);
  ASSERT_EQ(chaos.size(), 3u);
  const double loose = chaos[0].separation_time, mid = chaos[1].separation_time;
  ASSERT_TRUE(std::isfinite(loose));
  EXPECT_LT(loose, 0.5 * t_end);
  EXPECT_TRUE(std::isnan(mid) || mid > loose);
}

}  // namespace
}  // namespace epviz
