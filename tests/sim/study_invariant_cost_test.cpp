// The invariant-cost study finds, per method, the cheapest setting that keeps
// C1 and the fourth integral within the target; the chaos study's initial
// state is strongly chaotic.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/study_bench.hpp"
#include "sim/drift.hpp"
#include "sim/study_reference.hpp"

namespace epviz {
namespace {

TEST(StudyInvariantCost, ReachedRowsMeetTheTargetAndExactSplit4ReachesIt) {
  sim::StudyOptions o;
  o.quick = true;
  o.repeats = 1;
  o.methods = {sim::Method::rk4, sim::Method::exact_split4};
  const double t_end = 100.0, target = 1e-8;
  const auto rows = sim::invariant_cost_study(o, t_end, target);
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& r : rows) {
    EXPECT_EQ(r.study, "invariant_cost");
    EXPECT_EQ(r.text_of("case"), "kovalevskaya");
    EXPECT_EQ(*r.number("t_end"), t_end);
    EXPECT_EQ(*r.number("target"), target);
    EXPECT_GT(*r.number("cost"), 0.0);
    EXPECT_EQ(*r.number("cost"), *r.number("rhs_evals") + *r.number("flow_evals"));
    if (r.text_of("reached") == "yes") {
      EXPECT_LT(*r.number("drift_C1"), target) << *r.text_of("method");
      EXPECT_LT(*r.number("drift_extra"), target) << *r.text_of("method");
      EXPECT_EQ(r.text_of("status"), "ok");
    }
  }
  const auto& split4 = rows[1];
  ASSERT_EQ(split4.text_of("method"), "exact-split4");
  EXPECT_EQ(split4.text_of("reached"), "yes");
  EXPECT_LT(*split4.number("drift_C1"), target);
}

TEST(StudyInvariantCost, ChaosStateSeparatesFastAndRanksTolerances) {
  const auto& g = physics::preset(physics::Case::generic);
  const auto s = sim::chaos_initial_state();
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
      if (sim::state_error(ra.samples[i], rb.samples[i]) > 1e-3) {
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
  EXPECT_LT(sim::state_error(pa.samples.back(), pb.samples.back()), 1e-3);

  // dop853 separates later at tighter tolerance, and the loosest separates within the span.
  sim::StudyOptions o;
  o.quick = true;
  o.methods = {sim::Method::dop853};
  const auto chaos = sim::stability_chaos(o);
  ASSERT_EQ(chaos.size(), 3u);
  const double loose = *chaos[0].number("separation_time"), mid = *chaos[1].number("separation_time");
  ASSERT_TRUE(std::isfinite(loose));
  EXPECT_LT(loose, 0.5 * t_end);
  EXPECT_TRUE(std::isnan(mid) || mid > loose);
}

}  // namespace
}  // namespace epviz
