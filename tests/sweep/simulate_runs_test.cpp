// The runs `epviz simulate` makes of its fields, checked before any runs, and
// the summary it prints of each.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "io/bad_input.hpp"
#include "physics/cases.hpp"
#include "support/errors.hpp"
#include "sweep/simulate_runs.hpp"

namespace epviz::sweep {
namespace {

job::SimulationFields fixed_step(const std::string& case_name, double t_end, double step) {
  job::SimulationFields f;
  f.case_name.set(case_name, "--case");
  f.method.set("rk4", "--method");
  f.t_end.set(t_end, "--t-end");
  f.step.set(step, "--step");
  return f;
}

TEST(SimulateRuns, EveryPresetForCaseAll) {
  const auto one = fixed_step("euler", 1.0, 0.01);
  EXPECT_FALSE(runs_every_case(one));
  ASSERT_EQ(simulate_runs(one, std::nullopt).size(), 1u);
  const auto all = fixed_step("all", 1.0, 0.01);
  EXPECT_TRUE(runs_every_case(all));
  const auto specs = simulate_runs(all, std::nullopt);
  const auto& presets = physics::case_presets();
  ASSERT_EQ(specs.size(), presets.size());
  for (std::size_t i = 0; i < specs.size(); ++i) {
    EXPECT_EQ(specs[i].case_id, presets[i].id);
    EXPECT_EQ(specs[i].body.inertia, presets[i].body.inertia);
    EXPECT_EQ(specs[i].t_end, 1.0);
  }
}

// 10 time units at steps of 1e-3 are 1e4 steps: within a budget of 1e4,
// refused under one of 9999, with a message naming both options.
TEST(SimulateRuns, FixedStepsBeyondTheBudgetAreRefused) {
  const auto f = fixed_step("euler", 10.0, 1e-3);
  const auto within = simulate_runs(f, 10'001);
  ASSERT_EQ(within.size(), 1u);
  EXPECT_EQ(within[0].max_steps, 10'001);
  const auto message = test::error_of<io::BadInput>([&] { simulate_runs(f, 9'999); });
  EXPECT_EQ(message.rfind("--t-end: 10 with --step 0.001 needs 1e+04 steps", 0), 0u) << message;
  EXPECT_NE(message.find("--max-steps"), std::string::npos) << message;
  // An adaptive run is bounded while it runs, not refused beforehand.
  auto adaptive = f;
  adaptive.method.set("dop853", "--method");
  adaptive.step = {};
  EXPECT_EQ(simulate_runs(adaptive, 10).size(), 1u);
}

TEST(SimulateRuns, SummaryLines) {
  const auto spec = simulate_runs(fixed_step("euler", 1.0, 0.5), std::nullopt).at(0);
  sim::RunResult r;
  r.stats.steps = 2;
  r.effective_step = 0.5;
  sim::RunDrifts d;
  d.output.energy = 2.5e-7;
  const auto ok = run_summary(spec, r, d);
  EXPECT_EQ(ok.rfind("euler ", 0), 0u) << ok;
  EXPECT_NE(ok.find(" rk4 "), std::string::npos) << ok;
  EXPECT_NE(ok.find("step 0.5 "), std::string::npos) << ok;
  EXPECT_NE(ok.find("C1 2.5e-07"), std::string::npos) << ok;
  EXPECT_NE(ok.find("extra -\n"), std::string::npos) << ok;
  EXPECT_EQ(std::count(ok.begin(), ok.end(), '\n'), 3);

  r.failure = numerics::Failure{0.25, "rk4", numerics::FailureKind::non_finite, "NaN in the state"};
  const auto failed = run_summary(spec, r, d);
  EXPECT_EQ(std::count(failed.begin(), failed.end(), '\n'), 4);
  const auto last = failed.substr(failed.rfind('\n', failed.size() - 2) + 1);
  EXPECT_EQ(last.rfind(std::string(21, ' ') + "FAILED: rk4 failed at t = 0.25", 0), 0u) << last;
}

}  // namespace
}  // namespace epviz::sweep
