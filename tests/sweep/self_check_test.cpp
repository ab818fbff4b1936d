// The self-check of a sweep (sweep/self_check.hpp) on rows from real runs:
// which points it reruns, that rerunning them at the same accuracy changes
// nothing (its runs are the sweep's own), the colour bar's range it measures
// changes against, and the words it adds to an atlas's caption.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "job/resolve.hpp"
#include "sweep/atlas.hpp"
#include "sweep/point_run.hpp"
#include "sweep/self_check.hpp"
#include "sweep/sweep_point.hpp"

namespace epviz::sweep {
namespace {

using Json = nlohmann::json;

// Every row of `spec`, run as the sweep runs it.
std::vector<Json> rows_of(const SweepSpec& spec) {
  std::vector<Json> rows;
  ReferenceCache cache;
  for (long i = 0; i < spec.point_count(); ++i) {
    const PointFields f = point_fields(spec, i);
    const auto run =
        resolve_point(f, [](const job::SimulationFields& x) { return job::resolve(x); });
    rows.push_back(Json::parse(
        run_point(prepared_point(f, run), spec.hash, spec.reference, spec.ftle, &cache).line));
  }
  return rows;
}

// A sweep read from `text`, with its rows.
struct RanSweep {
  SweepSpec spec;
  std::vector<Json> rows;
};
RanSweep ran(const char* text) {
  RanSweep r{read_sweep(Json::parse(text), "test.sweep.json"), {}};
  r.rows = rows_of(r.spec);
  return r;
}

SweepSpec ftle_sweep(double tol) {
  Json j = Json::parse(R"({
      "simulation": {"case": "generic", "t_end": 20, "samples": 40, "method": "dop853",
                     "gamma": [0, 0, 1], "normalize_gamma": true, "omega": [1.0, 0.8, 0.6]},
      "axes": [{"field": "gamma[1]", "from": -0.8, "to": 0.8, "count": 4},
               {"field": "gamma[0]", "from": -0.8, "to": 0.8, "count": 5}],
      "ftle": {"window": 0.5},
      "atlas": [{"metric": "ftle", "x": "gamma[0]", "y": "gamma[1]", "min": 0, "max": 0.3}]})");
  j["simulation"]["tol"] = tol;
  return read_sweep(j, "small.sweep.json");
}

TEST(SelfCheckSample, AtLeastSixteenOrTwoPercentSpreadOverThePoints) {
  // 2 % of 4096 is 81.92: 82; of 1344, 26.88: 27; below 800 points, 16.
  const std::vector<std::pair<long, long>> sizes = {
      {1, 1}, {10, 10}, {16, 16}, {100, 16}, {800, 16}, {1344, 27}, {4096, 82}, {100000, 2000}};
  for (const auto& [points, expected] : sizes) {
    const auto s = self_check_sample(points);
    ASSERT_EQ(long(s.size()), expected) << points << " points";
    // Ascending, distinct, and one in each of `expected` equal stretches.
    for (std::size_t k = 0; k < s.size(); ++k) {
      EXPECT_GE(s[k] * long(s.size()), long(k) * points) << points << " points, k " << k;
      EXPECT_LT(s[k] * long(s.size()), long(k + 1) * points) << points << " points, k " << k;
    }
  }
  EXPECT_TRUE(self_check_sample(0).empty());
  EXPECT_EQ(self_check_sample(4096), self_check_sample(4096));  // every shard agrees
}

TEST(SelfCheck, AtTheSameAccuracyNothingChanges) {
  // The sample rerun with tol / 1 is the sweep's own run: each FTLE the same
  // to the last bit, so a check that reran anything else would show it.
  const auto spec = ftle_sweep(1e-9);
  const auto rows = rows_of(spec);
  const auto same = run_self_check(spec, rows, spec.atlases, 2, 1.0);
  ASSERT_EQ(same.metrics.size(), 1u);
  EXPECT_EQ(same.sampled, 16);
  EXPECT_EQ(same.metrics[0].compared, 16);
  EXPECT_EQ(same.metrics[0].largest_change, 0.0);
  EXPECT_TRUE(same.converged());
  // 100x tighter moves them, but by less than the sweep's own spread.
  const auto tighter = run_self_check(spec, rows, spec.atlases, 2);
  EXPECT_GT(tighter.metrics[0].largest_change, 0.0);
  for (const auto& v : tighter.values) {
    ASSERT_TRUE(v.value && v.tighter) << "point " << v.index;
    EXPECT_LE(std::abs(*v.tighter - *v.value), tighter.metrics[0].largest_change);
  }
}

TEST(SelfCheck, AFixedStepMethodsFtleIsRerunAtASmallerStep) {
  const auto [spec, rows] = ran(R"({
      "simulation": {"case": "generic", "t_end": 10, "samples": 20, "method": "rk4"},
      "axes": [{"field": "step", "values": [0.1, 0.05]}, {"field": "omega[0]", "values": [0.5, 1]}],
      "ftle": {"window": 0.5}})");
  const auto same = run_self_check(spec, rows, {}, 1, 1.0);
  EXPECT_EQ(same.metrics[0].largest_change, 0.0);
  const auto tighter = run_self_check(spec, rows, {}, 1);
  EXPECT_EQ(tighter.metrics[0].tightened, "step / 100^(1/order)");
  EXPECT_GT(tighter.metrics[0].largest_change, 0.0);  // another step: another run
  EXPECT_EQ(tighter.metrics[0].compared, 4);
}

TEST(SelfCheck, TheReferenceErrorAtTheSameReferenceIsTheRows) {
  const auto [spec, rows] = ran(R"({
      "simulation": {"case": "generic", "t_end": 10, "samples": 10, "max_drift": 0.1},
      "axes": [{"field": "method", "values": ["rk4", "gauss4"]},
               {"field": "step", "values": [0.5, 0.1]},
               {"field": "energy", "values": [1.5, 3.0, 6.0, 12.0]}],
      "reference": true})");
  const auto same = run_self_check(spec, rows, {}, 2, 1.0);
  ASSERT_EQ(same.metrics.size(), 1u);
  EXPECT_EQ(same.metrics[0].metric, "reference_error");
  EXPECT_EQ(same.metrics[0].compared, 16);
  EXPECT_EQ(same.metrics[0].largest_change, 0.0);
  // A reference 100x tighter: errors of 1e-3 and more do not notice it.
  const auto tighter = run_self_check(spec, rows, {}, 2);
  EXPECT_TRUE(tighter.converged());
  EXPECT_LT(tighter.metrics[0].largest_change, 1e-8);
}

TEST(SelfCheck, TheLimitIsAShareOfTheColourBar) {
  const std::vector<Json> rows = {{{"ftle", 0.1}}, {{"ftle", 0.25}}, {{"ftle", nullptr}}};
  AtlasRequest fixed{"ftle", "x", "y"};
  fixed.min = 0.0;
  fixed.max = 0.3;
  EXPECT_DOUBLE_EQ(colour_range("ftle", rows, {fixed}), 0.3);
  EXPECT_DOUBLE_EQ(colour_range("ftle", rows, {AtlasRequest{"ftle", "x", "y"}}), 0.15);
  EXPECT_DOUBLE_EQ(colour_range("ftle", rows, {}), 0.15);
  EXPECT_DOUBLE_EQ(colour_range("ftle", {{{"ftle", 0.2}}}, {}), 0.2);
}

TEST(SelfCheck, ACaptionSaysConvergedOrTightenTol) {
  SelfCheck c;
  c.sampled = 82;
  MetricCheck m;
  m.metric = "ftle";
  m.compared = 82;
  m.largest_change = 0.003;
  m.range = 0.3;
  m.limit = 0.015;
  c.metrics.push_back(m);
  EXPECT_EQ(self_check_caption(c, "ftle"), "FTLE converged to ±0.003 on 82 sampled points");
  EXPECT_EQ(self_check_caption(c, "steps"), "");
  c.metrics[0].largest_change = 0.04;
  EXPECT_FALSE(c.converged());
  EXPECT_EQ(self_check_caption(c, "ftle").rfind("not converged: tighten tol", 0), 0u)
      << self_check_caption(c, "ftle");
  c.metrics[0].largest_change = 0.001;
  c.metrics[0].one_sided = 1;  // a point that failed at one accuracy only
  EXPECT_FALSE(c.converged());
}

TEST(SelfCheck, TheAtlasShowsTTheWindowAndTheVerdict) {
  const auto spec = ftle_sweep(1e-9);
  const auto rows = rows_of(spec);
  const auto check = run_self_check(spec, rows, spec.atlases, 2);
  const auto figs = atlas_figures(rows, spec.atlases[0], spec.ftle, &check);
  ASSERT_EQ(figs.size(), 1u);
  const std::string& note = figs[0].heat_map.note;
  for (const char* w : {"T = 20", "FTLE window 0.5"})
    EXPECT_NE(note.find(w), std::string::npos) << w << " not in: " << note;
  const std::string& title = figs[0].heat_map.title;
  EXPECT_NE(title.find(self_check_caption(check, "ftle")), std::string::npos) << title;
  EXPECT_NE(title.find("on 16 sampled points"), std::string::npos) << title;
  // Without the sweep file's settings the window is said to be unknown, not left out.
  const auto bare = atlas_figures(rows, spec.atlases[0]);
  EXPECT_NE(bare[0].heat_map.note.find("T = 20"), std::string::npos) << bare[0].heat_map.note;
  EXPECT_NE(bare[0].heat_map.note.find("window unknown"), std::string::npos)
      << bare[0].heat_map.note;
}

TEST(SelfCheck, AnAtlasOverTKeepsTInItsCaption) {
  const auto [spec, rows] = ran(R"({
      "simulation": {"case": "generic", "t_end": 5, "samples": 10, "method": "dop853"},
      "axes": [{"field": "t_end", "values": [2, 4]}, {"field": "omega[0]", "values": [0.5, 1]}],
      "ftle": {"window": 0.5}})");
  const auto figs = atlas_figures(rows, parse_atlas_option("ftle:omega[0]:t_end"), spec.ftle);
  ASSERT_EQ(figs.size(), 1u);
  EXPECT_NE(figs[0].heat_map.note.find("T = 2 to 4"), std::string::npos) << figs[0].heat_map.note;
}

}  // namespace
}  // namespace epviz::sweep
