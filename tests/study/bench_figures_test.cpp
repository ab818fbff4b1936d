// Bench rows -> figure specifications: a chart per case and cost measure with
// a series per method, the drift chart with C₁ and the fourth integral, and the
// stability rows as one table.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "study/bench_figures.hpp"

namespace epviz {
namespace {

using study::StudyRow;

// A work-precision row of the "euler" case.
study::WorkPrecisionRow wp_row(const char* method, const char* formulation, double error,
                               double cpu_ms, long rhs_evals) {
  study::WorkPrecisionRow r;
  r.run.case_name = "euler";
  r.run.method = method;
  r.run.formulation = formulation;
  r.error = error;
  r.run.cpu_ms = cpu_ms;
  r.run.rhs_evals = rhs_evals;
  return r;
}

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
  EXPECT_EQ(figures[3].file_name, "stability.png");  // a heat map; no other stability rows
  EXPECT_TRUE(std::holds_alternative<chart::HeatMapSpec>(figures[3].content));
  // Its note names the integrals by their symbols, as the charts' keys do.
  const auto& note = std::get<chart::HeatMapSpec>(figures[3].content).note;
  EXPECT_NE(note.find("C₁ or |γ|² > 1"), std::string::npos) << note;

  const auto& cpu = std::get<chart::ChartSpec>(figures[0].content);
  EXPECT_TRUE(cpu.log_x && cpu.log_y);
  ASSERT_EQ(cpu.series.size(), 2u);  // dop853, rk4 (by name); the failed midpoint run has none
  EXPECT_EQ(cpu.series[0].name, "dop853");
  ASSERT_EQ(cpu.series[0].points.size(), 3u);
  EXPECT_DOUBLE_EQ(cpu.series[0].points[0].x, 0.01);
  EXPECT_DOUBLE_EQ(cpu.series[0].points[0].y, 1e-7);
  const auto& evals = std::get<chart::ChartSpec>(figures[1].content);
  EXPECT_DOUBLE_EQ(evals.series[1].points[2].x, 300.0);

  const auto& small_multiples = std::get<chart::ChartSpec>(figures[2].content);
  ASSERT_EQ(small_multiples.panels.size(), 1u);  // rk4's family only
  const auto& drift = small_multiples.panels[0];
  EXPECT_FALSE(drift.log_x);
  ASSERT_EQ(drift.series.size(), 2u);
  // The integrals by the symbols the renders use: the energy C₁, Kovalevskaya's K.
  EXPECT_EQ(drift.series[0].name, "rk4, C₁");
  EXPECT_EQ(drift.series[1].name, "rk4, K");
  ASSERT_EQ(drift.marker_legend.size(), 2u);
  EXPECT_EQ(drift.marker_legend[0].name, "C₁");
  EXPECT_EQ(drift.marker_legend[1].name, "K");
  EXPECT_DOUBLE_EQ(drift.series[0].points[0].y, 1e-10);  // drifts shown as magnitudes
  // The NaN point is left out, and so is the start's drift of 0 (t = 0).
  EXPECT_EQ(drift.series[1].points.size(), 18u);
}

// A method whose cost is not counted in right-hand side evaluations (a
// splitting's are exact sub-flows) has no series on the evaluations chart,
// and its legend does not name it.
TEST(BenchFigures, LegendsNameOnlySeriesDrawn) {
  auto rows = tiny_bench();
  auto split = wp_row("exact-split4", "direct", 1e-6, 0.02, 0);
  split.run.adaptive = false;
  split.run.flow_evals = 400;
  rows.emplace_back(split);
  const auto figures = study::bench_figures(rows);
  const auto names = [](const chart::ChartSpec& c) {
    std::vector<std::string> out;
    for (const auto& k : c.colour_legend) out.push_back(k.name);
    return out;
  };
  const auto& cpu = std::get<chart::ChartSpec>(figures[0].content);
  const auto& evals = std::get<chart::ChartSpec>(figures[1].content);
  EXPECT_EQ(cpu.series.size(), 3u);
  EXPECT_EQ(names(cpu), (std::vector<std::string>{"rk4", "dop853", "exact-split4"}));
  EXPECT_EQ(evals.series.size(), 2u);
  EXPECT_EQ(names(evals), (std::vector<std::string>{"rk4", "dop853"}));
}

// The drift chart as small multiples: a panel per method family, each
// holding only its family's series and naming only its methods, the families
// in the methods' order.
TEST(BenchFigures, DriftPanelPerMethodFamily) {
  std::vector<StudyRow> rows;
  for (const char* method : {"gauss6", "rk4", "exact-split4", "dop853", "midpoint"}) {
    study::DriftRow d;
    d.run.case_name = "kovalevskaya";
    d.run.method = method;
    d.run.formulation = "direct";
    d.series_t = {1.0, 2.0};
    d.series_drift_C1 = {1e-12, 2e-12};
    d.series_drift_extra = {1e-11, 3e-11};
    rows.emplace_back(d);
  }
  const auto figures = study::bench_figures(rows);
  ASSERT_EQ(figures.size(), 1u);
  const auto& chart = std::get<chart::ChartSpec>(figures[0].content);
  EXPECT_EQ(chart.title, "Relative drift of the integrals: kovalevskaya");
  const std::vector<std::pair<std::string, std::vector<std::string>>> expected{
      {"explicit Runge-Kutta", {"rk4", "dop853"}},
      {"implicit Gauss-Legendre (symplectic)", {"midpoint", "gauss6"}},
      {"splittings", {"exact-split4"}}};
  ASSERT_EQ(chart.panels.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const auto& panel = chart.panels[i];
    EXPECT_EQ(panel.title, expected[i].first);
    EXPECT_TRUE(panel.log_y);
    std::vector<std::string> named;
    for (const auto& k : panel.colour_legend) named.push_back(k.name);
    std::sort(named.begin(), named.end());
    auto want = expected[i].second;
    std::sort(want.begin(), want.end());
    EXPECT_EQ(named, want) << panel.title;
    EXPECT_EQ(panel.series.size(), 2 * want.size()) << panel.title;  // C1 and the 4th integral
    for (const auto& s : panel.series) {
      const std::string method = s.name.substr(0, s.name.find(", "));
      EXPECT_NE(std::find(want.begin(), want.end(), method), want.end()) << s.name;
    }
  }
}

// Colour by method, marker by formulation: a method keeps its colour across
// formulations and charts, and the legend names each colour and shape once.
TEST(BenchFigures, ColourByMethodMarkerByFormulation) {
  std::vector<StudyRow> rows;
  for (const char* f : {"direct", "riccati"})
    for (const char* method : {"rk4", "dop853"})
      rows.emplace_back(wp_row(method, f, 1e-6, 1.0, 100));
  const auto figures = study::bench_figures(rows);
  const auto& cpu = std::get<chart::ChartSpec>(figures[0].content);
  ASSERT_EQ(cpu.series.size(), 4u);
  std::map<std::string, int> colour_of_method;
  std::map<std::string, int> marker_of_formulation;
  for (const auto& s : cpu.series) {
    const bool riccati = s.name.find("riccati") != std::string::npos;
    const std::string method = s.name.find("rk4") != std::string::npos ? "rk4" : "dop853";
    ASSERT_GE(s.colour_key, 0);
    ASSERT_GE(s.marker_key, 0);
    auto [c, new_c] = colour_of_method.emplace(method, s.colour_key);
    EXPECT_EQ(c->second, s.colour_key) << s.name;
    auto [m, new_m] = marker_of_formulation.emplace(riccati ? "riccati" : "direct", s.marker_key);
    EXPECT_EQ(m->second, s.marker_key) << s.name;
  }
  EXPECT_NE(colour_of_method["rk4"], colour_of_method["dop853"]);
  EXPECT_NE(marker_of_formulation["direct"], marker_of_formulation["riccati"]);
  EXPECT_EQ(cpu.colour_legend.size(), 2u);
  EXPECT_EQ(cpu.marker_legend.size(), 2u);
  // The drift chart colours rk4 as the work-precision chart does.
  const auto drift = study::bench_figures(tiny_bench());
  const auto& d = std::get<chart::ChartSpec>(drift[2].content).panels.at(0);
  EXPECT_EQ(d.series[0].colour_key, colour_of_method["rk4"]);
  EXPECT_NE(d.series[0].marker_key, d.series[1].marker_key);  // C1 and the 4th integral
}

TEST(BenchFigures, StabilityHeatMapIsMethodByCase) {
  std::vector<StudyRow> rows;
  auto add = [&](const char* c, const char* m, double h_over_period) {
    study::MaxStepRow r;
    r.case_name = c;
    r.method = m;
    r.max_step_over_period = h_over_period;
    rows.emplace_back(r);
  };
  add("kovalevskaya", "rk4", 0.08);
  add("kovalevskaya", "gauss4", 0.3);
  add("lagrange", "rk4", 0.05);
  add("lagrange", "gauss4", study::kNaN);  // fails even at the smallest step
  const auto h = study::stability_heat_map(rows);
  EXPECT_EQ(h.rows, (std::vector<std::string>{"rk4", "gauss4"}));
  EXPECT_EQ(h.columns, (std::vector<std::string>{"kovalevskaya", "lagrange"}));
  ASSERT_EQ(h.values.size(), 2u);
  EXPECT_DOUBLE_EQ(h.values[0][0], 0.08);
  EXPECT_DOUBLE_EQ(h.values[0][1], 0.05);
  EXPECT_DOUBLE_EQ(h.values[1][0], 0.3);
  EXPECT_TRUE(std::isnan(h.values[1][1]));
  // The table of the other studies leaves the largest-step rows to the heat map.
  EXPECT_TRUE(study::stability_table(rows, false).rows.empty());
  EXPECT_EQ(study::stability_table(rows).rows.size(), 4u);
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
