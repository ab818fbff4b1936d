// Stability studies push methods into their failure regimes: the failure must
// be detected and reported (time, method, reason) and the robust method must
// succeed on the same case.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/euler_closed_form.hpp"
#include "study/bench_figures.hpp"
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

// The chaos study's reference is DOP853 at 1e-14 checked by Gauss6 at a
// step below any the study takes. On a regular motion both follow the closed
// form and agree throughout; on the chaotic state they part (round-off grows
// like e^(lambda t)), and the reference is trusted only until they do.
TEST(StudyReference, CheckedReferenceAgreesWhereTheMotionAllowsIt) {
  const auto& e = physics::preset(physics::Case::euler);
  physics::InitialState regular;
  regular.omega = {1.0, 0.3, 0.2};
  regular.gamma = {0.0, 0.0, 1.0};
  const auto ref = study::compute_checked_reference(e.body, regular, 20.0, 400, 0.05 / 128);
  const physics::EulerClosedForm exact(e.body.inertia, regular.omega);
  for (const auto& s : ref.samples) EXPECT_LT((s.omega - exact.omega(s.t)).norm(), 1e-10) << s.t;
  EXPECT_LT(ref.self_check(), 1e-10);
  EXPECT_EQ(ref.trusted_until(1e-4), 20.0);

  const auto& g = physics::preset(physics::Case::generic);
  const auto chaos = study::compute_checked_reference(g.body, study::chaos_initial_state(), 100.0,
                                                      2000, 0.05 / 128);
  EXPECT_GT(chaos.self_check(), 1e-4) << "the two references never part on a chaotic orbit";
  const double horizon = chaos.trusted_until(1e-4);
  EXPECT_GT(horizon, 10.0);
  EXPECT_LT(horizon, 100.0);
}

// Where the reference is trusted a separation counts; beyond it a run that
// has not separated is undecided, not "never separates".
TEST(StudyStability, ARunIsJudgedOnlyWhereTheReferenceIsTrusted) {
  study::CheckedReference ref;
  for (int k = 0; k <= 10; ++k) {
    sim::Sample s;
    s.t = k;
    ref.samples.push_back(s);
    ref.disagreement.push_back(k <= 5 ? 1e-6 : 1e-2);  // the two halves part after t = 5
  }
  const auto run_off_from = [&](double t_off) {
    std::vector<sim::Sample> run = ref.samples;
    for (auto& s : run)
      if (s.t >= t_off) s.omega.x() += 0.5;
    return run;
  };
  const auto judged = [&](const std::vector<sim::Sample>& run, const study::CheckedReference& r) {
    study::ChaosRow row;
    row.threshold = 1e-3;
    study::judge_separation(row, run, r);
    return row;
  };
  const auto early = judged(run_off_from(3.0), ref);
  EXPECT_TRUE(early.separated);
  EXPECT_EQ(early.separation_time, 3.0);
  EXPECT_TRUE(early.reference_decides);
  EXPECT_EQ(early.reference_horizon, 5.0);
  for (double t_off : {7.0, 100.0}) {  // after the horizon, or never
    const auto late = judged(run_off_from(t_off), ref);
    EXPECT_FALSE(late.separated) << t_off;
    EXPECT_FALSE(late.reference_decides) << t_off;
  }
  auto trusted = ref;
  for (auto& d : trusted.disagreement) d = 1e-9;
  const auto never = judged(run_off_from(100.0), trusted);
  EXPECT_FALSE(never.separated);
  EXPECT_TRUE(never.reference_decides);
}

// The study's rows say how far the reference reaches, and its figure hatches
// the cells it cannot decide, labelled, instead of the grey of "none".
TEST(StudyStability, ChaosCellsTheReferenceCannotDecideAreHatched) {
  const auto rows =
      study::stability_chaos(testing::quick_options({sim::Method::dop853, sim::Method::gauss6}));
  ASSERT_EQ(rows.size(), 6u);
  std::vector<study::StudyRow> all;
  for (const auto& r : rows) {
    EXPECT_GT(r.reference_horizon, 10.0);
    EXPECT_LE(r.reference_horizon, r.run.t_end);
    if (r.separated) {
      EXPECT_LE(r.separation_time, r.reference_horizon);
    }
    EXPECT_EQ(r.reference_decides, r.separated || r.reference_horizon >= r.run.t_end);
    all.push_back(r);
  }
  // DOP853 at tol 1e-6 leaves the motion within the reference's reach; Gauss6
  // at the finest step follows it past (where the old reference, Gauss6
  // itself, called it "never separates").
  EXPECT_TRUE(rows.front().separated);
  EXPECT_TRUE(rows.front().reference_decides);
  EXPECT_FALSE(rows.back().reference_decides);
  const auto h = study::chaos_heat_map(all);
  ASSERT_EQ(h.undecided.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    ASSERT_EQ(h.undecided[i].size(), 3u);
    for (std::size_t j = 0; j < 3; ++j) {
      EXPECT_EQ(h.undecided[i][j], !rows[3 * i + j].reference_decides);
      if (h.undecided[i][j]) {
        EXPECT_TRUE(std::isnan(h.values[i][j]));
      }
    }
  }
  EXPECT_EQ(h.undecided_label, "reference not converged");
  EXPECT_NE(h.note.find("Gauss6"), std::string::npos) << h.note;
}

}  // namespace
}  // namespace epviz
