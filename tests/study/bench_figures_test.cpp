// Bench rows -> figure specifications: a chart per case and cost measure with
// a series per method, the drift chart with C1 and the fourth integral, and the
// stability rows as one table.
#include <gtest/gtest.h>

#include <cmath>

#include "study/bench_figures.hpp"

namespace epviz {
namespace {

using study::StudyRow;

std::vector<StudyRow> tiny_bench() {
  std::vector<StudyRow> rows;
  for (const char* method : {"rk4", "dop853"})
    for (int k = 0; k < 3; ++k) {
      study::WorkPrecisionRow r;
      r.run.case_name = "euler";
      r.run.method = method;
      r.run.formulation = "direct";
      r.error = std::pow(10.0, -3.0 - 2.0 * k);
      r.run.cpu_ms = 0.01 * (3 - k);  // listed from the dearest: the chart sorts by cost
      r.run.rhs_evals = 100 * (3 - k);
      rows.emplace_back(r);
    }
  study::WorkPrecisionRow failed;
  failed.run.case_name = "euler";
  failed.run.method = "midpoint";
  failed.run.ok = false;
  rows.emplace_back(failed);  // no error: no series
  study::DriftRow d;
  d.run.case_name = "kovalevskaya";
  d.run.method = "rk4";
  d.run.formulation = "direct";
  for (int i = 0; i < 20; ++i) {
    d.series_t.push_back(5.0 * i);
    d.series_drift_C1.push_back(-1e-10 * (i + 1));
    d.series_drift_extra.push_back(i == 3 ? study::kNaN : 1e-9 * i);
  }
  rows.emplace_back(d);
  study::MaxStepRow m;
  m.case_name = "kovalevskaya";
  m.method = "rk4";
  m.max_step = 0.33;
  m.max_step_over_period = 0.084;
  m.failure_reason = "blew up";
  rows.emplace_back(m);
  return rows;
}

TEST(BenchFigures, ChartsFromRows) {
  const auto figures = study::bench_figures(tiny_bench());
  ASSERT_EQ(figures.size(), 4u);
  EXPECT_EQ(figures[0].file_name, "work_precision_euler.png");
  EXPECT_EQ(figures[1].file_name, "work_precision_evals_euler.png");
  EXPECT_EQ(figures[2].file_name, "drift_kovalevskaya.png");
  EXPECT_EQ(figures[3].file_name, "stability.png");

  const auto& cpu = std::get<chart::ChartSpec>(figures[0].content);
  EXPECT_TRUE(cpu.log_x && cpu.log_y);
  ASSERT_EQ(cpu.series.size(), 2u);  // dop853, rk4 (by name); the failed midpoint run has none
  EXPECT_EQ(cpu.series[0].name, "dop853");
  ASSERT_EQ(cpu.series[0].points.size(), 3u);
  EXPECT_DOUBLE_EQ(cpu.series[0].points[0].x, 0.01);
  EXPECT_DOUBLE_EQ(cpu.series[0].points[0].y, 1e-7);
  const auto& evals = std::get<chart::ChartSpec>(figures[1].content);
  EXPECT_DOUBLE_EQ(evals.series[1].points[2].x, 300.0);

  const auto& drift = std::get<chart::ChartSpec>(figures[2].content);
  EXPECT_FALSE(drift.log_x);
  ASSERT_EQ(drift.series.size(), 2u);
  EXPECT_EQ(drift.series[0].name, "rk4, C1");
  EXPECT_EQ(drift.series[1].name, "rk4, 4th integral");
  EXPECT_DOUBLE_EQ(drift.series[0].points[0].y, 1e-10);  // drifts shown as magnitudes
  EXPECT_EQ(drift.series[1].points.size(), 19u);         // the NaN point is left out
}

TEST(BenchFigures, StabilityTable) {
  const auto t = study::stability_table(tiny_bench());
  ASSERT_EQ(t.rows.size(), 1u);
  const std::vector<std::string> expected{
      "max_step", "kovalevskaya", "rk4", "direct", "limit", "max step 0.33, h/period 0.084"};
  EXPECT_EQ(t.rows[0], expected);
  EXPECT_TRUE(study::stability_table({}).rows.empty());
}

}  // namespace
}  // namespace epviz
