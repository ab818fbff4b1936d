// The recommendation of `epviz bench --job`: the rule on hand-made rows (the
// cheapest run meeting the target, else the closest), and on a real study of
// a small body the evidence agrees with the rows it was chosen from.
#include <gtest/gtest.h>

#include <cmath>

#include "study/quick_options.hpp"
#include "study/recommendation.hpp"
#include "study/work_precision.hpp"

namespace epviz {
namespace {

using study::WorkPrecisionRow;

WorkPrecisionRow row(const std::string& method, double error, double cpu_ms, long evals,
                     const std::string& impl = "epviz", bool ok = true) {
  WorkPrecisionRow r;
  r.run.impl = impl;
  r.run.case_name = "custom";
  r.run.formulation = "direct";
  r.run.method = method;
  r.run.tol = 1e-9;
  r.run.cpu_ms = cpu_ms;
  r.run.rhs_evals = evals;
  r.run.ok = ok;
  r.error = error;
  return r;
}

std::vector<const WorkPrecisionRow*> pointers(const std::vector<WorkPrecisionRow>& rows) {
  std::vector<const WorkPrecisionRow*> out;
  for (const auto& r : rows) out.push_back(&r);
  return out;
}

TEST(Recommendation, CheapestOfThoseMeetingTheTarget) {
  const std::vector<WorkPrecisionRow> rows{
      row("rk4", 5e-7, 0.1, 400),                        // cheapest of all, misses 1e-8
      row("dop853", 3e-9, 0.9, 900),                     // meets, dearer
      row("dopri5", 8e-9, 0.4, 1200),                    // meets, cheapest in time: the answer
      row("gauss6", 1e-12, 2.0, 5000),                   // meets, smallest error, dearest
      row("midpoint", 1e-10, 0.01, 10, "epviz", false),  // failed: never chosen
      row("rk8pd", 1e-9, 0.05, 300, "gsl"),              // a peer: not among epviz's candidates
  };
  const auto all = pointers(rows);
  const auto* chosen = study::cheapest_meeting(all, 1e-8);
  ASSERT_NE(chosen, nullptr);
  EXPECT_EQ(chosen->run.method, "dopri5");
  // A tighter target leaves fewer candidates; the cheapest of them wins.
  EXPECT_EQ(study::cheapest_meeting(all, 5e-9)->run.method, "dop853");
  EXPECT_EQ(study::cheapest_meeting(all, 1e-11)->run.method, "gauss6");
  // The target is met at equality.
  EXPECT_EQ(study::cheapest_meeting(all, 3e-9)->run.method, "dop853");
  // The peers are chosen among themselves.
  EXPECT_EQ(study::cheapest_meeting(all, 1e-8, "gsl")->run.method, "rk8pd");
}

TEST(Recommendation, EqualTimeGoesToFewerEvaluations) {
  const std::vector<WorkPrecisionRow> rows{row("rk4", 1e-9, 0.5, 800),
                                           row("dop853", 1e-9, 0.5, 600)};
  EXPECT_EQ(study::cheapest_meeting(pointers(rows), 1e-8)->run.method, "dop853");
}

TEST(Recommendation, NoneMeetsTheTargetThenTheClosest) {
  const std::vector<WorkPrecisionRow> rows{
      row("rk4", 5e-5, 0.1, 400), row("dop853", 2e-7, 0.9, 900), row("splitting", NAN, 0.2, 100),
      row("gauss4", 1e-3, 0.3, 300)};
  const auto all = pointers(rows);
  EXPECT_EQ(study::cheapest_meeting(all, 1e-8), nullptr);
  const auto* closest = study::closest_to_target(all);
  ASSERT_NE(closest, nullptr);
  EXPECT_EQ(closest->run.method, "dop853");
  EXPECT_EQ(study::closest_to_target({}), nullptr);
}

// A job of a preset's case shares the case name with the preset's rows: the
// recommendation takes only the rows at the job's final time.
TEST(Recommendation, OnlyTheRowsAtTheJobsFinalTime) {
  study::Problem p = study::preset_problem(physics::Case::euler);
  p.t_end = 2.0;
  auto preset = row("rk4", 1e-12, 0.001, 10);  // cheaper, but the preset's run to t = 10
  preset.run.case_name = "euler";
  preset.run.t_end = 10.0;
  auto job = row("dop853", 1e-9, 1.0, 500);
  job.run.case_name = "euler";
  job.run.t_end = 2.0;
  const std::vector<study::StudyRow> rows{preset, job};
  const auto rec = study::recommend(p, rows, 1e-8);
  ASSERT_TRUE(rec.choice.has_value());
  EXPECT_EQ(rec.choice->run.method, "dop853");
  EXPECT_EQ(rec.compared, 1);
  EXPECT_TRUE(std::isfinite(rec.choice->drift));  // re-run at tol 1e-9 to t = 2
}

// On measured rows of a small body: the choice is one of the rows, meets the
// target, and no cheaper row does; its drift is measured, not left out.
TEST(Recommendation, OnAStudyOfABodyOfOnesOwn) {
  auto o = testing::quick_options({sim::Method::dop853, sim::Method::rk4}, {},
                                  {sim::Formulation::direct});
  study::Problem p;
  p.name = "custom";
  p.body = {Eigen::Vector3d(3.0, 2.0, 1.2), Eigen::Vector3d(0.3, 0.1, 0.5), 1.0};
  p.initial = {Eigen::Vector3d(0.4, -0.8, 1.1), Eigen::Vector3d(0.0, 0.6, 0.8)};
  p.t_end = 3.0;
  o.custom = p;
  const auto rows = study::work_precision_study(o);
  const auto rec = study::recommend(p, rows, 1e-8);
  EXPECT_EQ(rec.t_end, 3.0);
  ASSERT_TRUE(rec.choice.has_value());
  ASSERT_TRUE(rec.met);
  EXPECT_LE(rec.choice->error, 1e-8);
  EXPECT_EQ(rec.choice->run.t_end, 3.0);
  for (const auto* r : study::rows_of<WorkPrecisionRow>(rows))
    if (r->run.ok && r->error <= 1e-8) {
      EXPECT_GE(r->run.cpu_ms, rec.choice->run.cpu_ms);
    }
  EXPECT_GT(rec.choice->drift_samples, 0);
  EXPECT_TRUE(std::isfinite(rec.choice->drift));
  EXPECT_LT(rec.choice->drift, 1e-4);
  const std::string text = study::recommendation_text(rec);
  EXPECT_NE(text.find(rec.choice->run.method), std::string::npos) << text;
  EXPECT_NE(text.find("t = 3"), std::string::npos) << text;
}

}  // namespace
}  // namespace epviz
