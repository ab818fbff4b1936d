// The work-precision study on a body of one's own (`epviz bench --job`): its
// rows are named "custom", measured against a reference of that body, and
// the presets are left out unless asked for.
#include <gtest/gtest.h>

#include <cmath>

#include "io/bad_input.hpp"
#include "physics/cases.hpp"
#include "study/quick_options.hpp"
#include "study/work_precision.hpp"
#include "support/errors.hpp"

namespace epviz {
namespace {

study::StudyOptions custom_options() {
  auto o = testing::quick_options({sim::Method::dop853, sim::Method::rk4}, {},
                                  {sim::Formulation::direct});
  study::Problem p;
  p.id = physics::Case::custom;
  p.name = "custom";
  p.body = {Eigen::Vector3d(1.0, 1.7, 2.3), Eigen::Vector3d(0.2, -0.1, 0.4), 1.0};
  p.initial = {Eigen::Vector3d(0.5, 1.2, -0.3), Eigen::Vector3d(0.0, 0.6, 0.8)};
  o.custom = p;
  return o;
}

TEST(CustomProblem, OnlyTheCustomBodyUnlessPresetsAreNamed) {
  auto o = custom_options();
  EXPECT_TRUE(study::cases_of(o).empty());
  ASSERT_EQ(study::problems_of(o).size(), 1u);
  o.cases = {physics::Case::euler};
  const auto both = study::problems_of(o);
  ASSERT_EQ(both.size(), 2u);
  EXPECT_EQ(both[0].name, "euler");
  EXPECT_EQ(both[1].name, "custom");
  // Without a custom body, no cases means every preset.
  EXPECT_EQ(study::cases_of(study::StudyOptions{}).size(), physics::case_presets().size());
}

// A job's checked run becomes the problem it describes, named after its case.
TEST(CustomProblem, FromARun) {
  const auto mine = custom_options().custom.value();
  const auto back = study::run_problem(
      study::problem_run(mine, sim::Method::dop853, sim::Formulation::direct, 1.0, 2));
  EXPECT_EQ(back.id, physics::Case::custom);
  EXPECT_EQ(back.name, "custom");
  EXPECT_EQ(back.body.inertia, mine.body.inertia);
  EXPECT_EQ(back.body.com, mine.body.com);
  EXPECT_EQ(back.initial.omega, mine.initial.omega);
  EXPECT_EQ(back.initial.gamma, mine.initial.gamma);
  const auto euler = study::preset_problem(physics::Case::euler);
  EXPECT_EQ(study::run_problem(
                study::problem_run(euler, sim::Method::rk4, sim::Formulation::direct, 1.0, 2))
                .name,
            "euler");
}

// --cases: presets by name; "custom" only when there is a body of one's own,
// and then left out of the presets.
TEST(CustomProblem, CaseList) {
  EXPECT_TRUE(study::parse_case_list("", false).empty());
  const auto two = study::parse_case_list("kovalevskaya,euler", false);
  ASSERT_EQ(two.size(), 2u);
  EXPECT_EQ(two[0], physics::Case::kovalevskaya);
  EXPECT_EQ(two[1], physics::Case::euler);
  const auto with_custom = study::parse_case_list("custom,lagrange", true);
  ASSERT_EQ(with_custom.size(), 1u);
  EXPECT_EQ(with_custom[0], physics::Case::lagrange);

  const auto custom = test::error_of<io::BadInput>([] { study::parse_case_list("custom", false); });
  EXPECT_EQ(custom.rfind("--cases: 'custom' needs --job", 0), 0u) << custom;
  const auto unknown =
      test::error_of<io::BadInput>([] { study::parse_case_list("euler,nope", false); });
  EXPECT_EQ(unknown.rfind("--cases: unknown case 'nope'", 0), 0u) << unknown;
  for (const auto& p : physics::case_presets())
    EXPECT_NE(unknown.find(p.name), std::string::npos) << unknown;
  EXPECT_EQ(unknown.find("custom"), std::string::npos) << unknown;
  const auto unknown_with_job =
      test::error_of<io::BadInput>([] { study::parse_case_list("nope", true); });
  EXPECT_NE(unknown_with_job.find(", custom)"), std::string::npos) << unknown_with_job;
}

TEST(CustomProblem, WorkPrecisionRowsOfTheCustomBody) {
  const auto rows = study::work_precision_study(custom_options());
  const auto runs = study::rows_of<study::WorkPrecisionRow>(rows);
  const auto refs = study::rows_of<study::ReferenceRow>(rows);
  ASSERT_EQ(refs.size(), 1u);
  EXPECT_EQ(refs[0]->case_name, "custom");
  ASSERT_GE(runs.size(), 6u);
  std::vector<double> dop853_errors;
  for (const auto* r : runs) {
    EXPECT_EQ(r->run.case_name, "custom");
    if (r->run.method == "dop853" && r->run.ok) dop853_errors.push_back(r->error);
  }
  // The error falls as the tolerance tightens: it is measured, not made up.
  ASSERT_GE(dop853_errors.size(), 3u);
  EXPECT_LT(dop853_errors.back(), 1e-3 * dop853_errors.front());
  for (double e : dop853_errors) EXPECT_TRUE(std::isfinite(e));
}

}  // namespace
}  // namespace epviz
