// Runs that would not end in reasonable time: adaptive runs stop at their step
// budget (exit 3, a failure naming the budget); fixed-step runs whose number of
// steps is known to exceed it are refused before any work (exit 2).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/cli.hpp"

namespace epviz {
namespace {

TEST(StepBudget, AdaptiveRunEndsAtItsBudget) {
  test::TempDir dir;
  const auto [r, report] =
      test::run_with_report("simulate --case lagrange --t-end 1e300 --max-steps 20000", dir);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("step budget of 20000 steps exhausted"), std::string::npos) << r.err;
  EXPECT_EQ(report["failure_kind"], "step_budget");
  EXPECT_LE(report["steps"].get<long>(), 20000);
}

TEST(StepBudget, DefaultBudgetIsNotHitByANormalRun) {
  test::TempDir dir;
  const auto r = test::run_epviz("simulate --case kovalevskaya --tol 1e-13", dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST(StepBudget, AbsurdFixedStepRunIsRefusedBeforeWork) {
  test::TempDir dir;
  const auto r = test::run_epviz("simulate --case lagrange --method rk4 --t-end 5e6", dir);
  test::expect_bad_input(r, "--t-end");
  EXPECT_NE(r.err.find("step budget"), std::string::npos) << r.err;
}

TEST(StepBudget, NoProgressLineWhenStderrIsNotATerminal) {
  test::TempDir dir;
  const auto r = test::run_epviz("simulate --case euler --samples 1000", dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find('\r'), std::string::npos) << r.err;
}

}  // namespace
}  // namespace epviz
