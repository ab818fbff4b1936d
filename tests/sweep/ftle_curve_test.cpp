// λ(T), the FTLE over the first T of a run (sweep/point_run.hpp,
// sweep/ftle_curves.hpp): each point of the curve is the exponent a run that
// ends at that T measures, and the curves behave as the theory says: a
// regular orbit's falls like ln T / T, a chaotic one's levels off.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "physics/cases.hpp"
#include "sim/run_spec.hpp"
#include "sweep/ftle_curves.hpp"
#include "sweep/point_run.hpp"
#include "sweep/sweep_runner.hpp"
#include "sweep/sweep_spec.hpp"

namespace epviz::sweep {
namespace {

TEST(FtleCurve, EachPointIsTheExponentOfTheRunThatEndsThere) {
  sim::RunSpec run = sim::preset_run(physics::Case::generic, sim::Method::dop853,
                                     sim::Formulation::direct, 20.0, 1);
  const FtleSettings settings{1e-8, 0.5, true};
  const FtleResult r = ftle_result(run, settings);
  ASSERT_TRUE(r.value);
  // 40 windows: k = 1, 2, 4, 8, 16, 32 and the last, 40.
  ASSERT_EQ(r.curve.size(), 7u);
  const double expected_t[] = {0.5, 1, 2, 4, 8, 16, 20};
  for (std::size_t i = 0; i < r.curve.size(); ++i) {
    EXPECT_EQ(r.curve[i].t, expected_t[i]);
    sim::RunSpec shorter = run;
    shorter.t_end = r.curve[i].t;
    const auto lambda = finite_time_lyapunov(shorter, settings);
    ASSERT_TRUE(lambda) << r.curve[i].t;
    EXPECT_EQ(r.curve[i].lambda, *lambda) << "T = " << r.curve[i].t;
  }
  EXPECT_EQ(r.curve.back().lambda, *r.value);
  // Without "curve", none is kept.
  EXPECT_TRUE(ftle_result(run, FtleSettings{1e-8, 0.5, false}).curve.empty());
}

// The shipped λ(T) sweep: the Lagrange and Kovalevskaya tops (integrable) and
// the generic body from one state, T = 1000.
TEST(FtleCurve, RegularOrbitsFallLikeLnTOverTAndTheChaoticOneLevelsOff) {
  const SweepSpec spec = read_sweep_file(std::filesystem::path(EPVIZ_SOURCE_DIR) /
                                         "render_jobs/ftle_curves.sweep.json");
  ASSERT_TRUE(spec.ftle && spec.ftle->curve);
  const auto points = pending_points(spec, {0, 3}, {});
  ASSERT_EQ(points.size(), 3u);
  const auto at = [](const FtleResult& r, double t) {
    for (const auto& p : r.curve)
      if (p.t == t) return p.lambda;
    ADD_FAILURE() << "no point at T = " << t;
    return std::nan("");
  };
  for (const auto& p : points) {
    const FtleResult r = ftle_result(p.run, *spec.ftle);
    ASSERT_TRUE(r.value) << p.axes;
    const double t_end = r.curve.back().t;
    ASSERT_EQ(t_end, 1000.0);
    if (p.axes.find("generic") == std::string::npos) {
      // λ(T) T / ln T settles: within 15 % from T = 256 to 1000, where λ
      // itself falls by a factor of 3.
      const double c256 = at(r, 256) * 256 / std::log(256.0);
      const double c1000 = *r.value * 1000 / std::log(1000.0);
      EXPECT_NEAR(c1000 / c256, 1.0, 0.15) << p.axes;
      EXPECT_LT(*r.value, 0.01) << p.axes;
      EXPECT_GT(at(r, 256) / *r.value, 2.5) << p.axes;
    } else {
      // Levels off: within 30 % from T = 256 on, and well above the regular ones.
      EXPECT_GT(*r.value, 0.05) << p.axes;
      EXPECT_LT(at(r, 256) / *r.value, 1.3) << p.axes;
      EXPECT_GT(at(r, 256) / *r.value, 1 / 1.3) << p.axes;
    }
  }
}

TEST(FtleCurve, TheChartHasALinePerPointAndTheGuide) {
  nlohmann::json a, b, c;
  a["index"] = 0;
  a["axes"] = {{"case", "lagrange"}};
  a["ftle_curve"] = {{1.0, 0.2}, {2.0, 0.1}, {4.0, 0.05}, {8.0, 0.02}};
  b["index"] = 1;
  b["axes"] = {{"gamma[0]", 0.25}};
  b["ftle_curve"] = {{1.0, 0.3}, {8.0, 0.12}};
  c["index"] = 2;  // no curve: not drawn
  const auto f = ftle_curve_figure({a, b, c}, FtleSettings{1e-8, 1.0, true});
  ASSERT_TRUE(f);
  const auto& chart = std::get<chart::ChartSpec>(f->content);
  ASSERT_EQ(chart.series.size(), 3u);
  EXPECT_EQ(chart.series[0].name, "case lagrange");
  EXPECT_EQ(chart.series[1].name, "γ₁ = 0.25");
  EXPECT_TRUE(chart.log_x && chart.log_y);
  // The guide goes through the lowest last point: (8, 0.02).
  const auto& guide = chart.series[2];
  const double scale = 0.02 * 8 / std::log(8.0);
  for (const auto& p : guide.points) EXPECT_NEAR(p.y, scale * std::log(p.x) / p.x, 1e-15);
  EXPECT_NEAR(guide.points.back().x, 8.0, 1e-12);
  // A line without markers (the curves have theirs), smooth on the log axes.
  EXPECT_EQ(guide.style, chart::SeriesStyle::line);
  EXPECT_EQ(chart.series[0].style, chart::SeriesStyle::lines_and_markers);
  EXPECT_GE(guide.points.size(), 40u);
  EXPECT_FALSE(ftle_curve_figure({c}, std::nullopt));
}

// A regular orbit's negative λ at small T stays in the series (the painter
// marks it under the log axis, tests/paint/chart_nonpositive_test.cpp) and
// the chart names that row.
TEST(FtleCurve, NegativeLambdaIsKeptForTheRowUnderTheLogAxis) {
  nlohmann::json a;
  a["index"] = 0;
  a["axes"] = {{"case", "lagrange"}};
  a["ftle_curve"] = {{1.0, -0.16}, {2.0, -0.04}, {4.0, 0.0}, {8.0, 0.03}};
  const auto f = ftle_curve_figure({a}, std::nullopt);
  ASSERT_TRUE(f);
  const auto& chart = std::get<chart::ChartSpec>(f->content);
  int nonpositive = 0;
  for (const auto& p : chart.series.at(0).points) nonpositive += p.y <= 0.0;
  EXPECT_EQ(nonpositive, 3);
  EXPECT_EQ(chart.nonpositive_label, "λ ≤ 0");
}

}  // namespace
}  // namespace epviz::sweep
