// Which way an atlas's axes run: numeric axes ascend (x to the right, y
// upwards, i.e. the y axis's largest value in the heat map's first row) even
// when the sweep lists them from the largest; names keep the sweep's order.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "sweep/atlas.hpp"

namespace epviz::sweep {
namespace {

using Json = nlohmann::json;

// A run that fails at a time that names its point: 100 * step + energy.
Json row(long index, const char* method, double step, double energy) {
  return {{"index", index},
          {"axes", {{"method", method}, {"step", step}, {"energy", energy}}},
          {"failure", Json{{"t", 100.0 * step + energy}}},
          {"t_end", 1000.0}};
}

std::vector<Json> descending_sweep() {
  std::vector<Json> rows;
  long i = 0;
  for (const char* m : {"rk4", "midpoint"})
    for (double step : {0.4, 0.2, 0.1})      // largest first, as the stability atlas
      for (double energy : {8.0, 2.0, 4.0})  // in no order
        rows.push_back(row(i++, m, step, energy));
  return rows;
}

TEST(AtlasOrientation, NumericAxesAscendRightAndUp) {
  const auto figs =
      atlas_figures(descending_sweep(), parse_atlas_option("time_to_failure:energy:step"));
  ASSERT_EQ(figs.size(), 2u);  // one per method
  const auto& h = figs[0].heat_map;
  EXPECT_EQ(h.columns, (std::vector<std::string>{"2", "4", "8"}));
  EXPECT_EQ(h.rows, (std::vector<std::string>{"0.4", "0.2", "0.1"}));  // top to bottom
  const double steps[] = {0.4, 0.2, 0.1}, energies[] = {2.0, 4.0, 8.0};
  ASSERT_EQ(h.values.size(), 3u);
  for (int r = 0; r < 3; ++r) {
    ASSERT_EQ(h.values[r].size(), 3u);
    for (int c = 0; c < 3; ++c)
      EXPECT_DOUBLE_EQ(h.values[r][c], 100.0 * steps[r] + energies[c]) << r << "," << c;
  }
  EXPECT_EQ(h.x_label, "energy C₁");
  EXPECT_EQ(h.y_label, "step");
}

TEST(AtlasOrientation, NamesKeepTheSweepOrderTopDown) {
  const auto figs =
      atlas_figures(descending_sweep(), parse_atlas_option("largest_stable:step:energy:method"));
  ASSERT_EQ(figs.size(), 1u);
  const auto& h = figs[0].heat_map;
  EXPECT_EQ(h.rows, (std::vector<std::string>{"rk4", "midpoint"}));
  EXPECT_EQ(h.columns, (std::vector<std::string>{"2", "4", "8"}));
  // Every run failed: no cell has a value, and the grey says why.
  for (const auto& r : h.values)
    for (double v : r) EXPECT_TRUE(std::isnan(v));
  EXPECT_EQ(h.missing, "every step failed");
}

TEST(AtlasOrientation, RangeAndScaleReachTheHeatMap) {
  auto q = parse_atlas_option("time_to_failure:energy:step");
  q.min = 0.0;
  q.max = 50.0;
  const auto figs = atlas_figures(descending_sweep(), q);
  const auto& h = figs[0].heat_map;
  EXPECT_DOUBLE_EQ(h.range_min, 0.0);
  EXPECT_DOUBLE_EQ(h.range_max, 50.0);
  EXPECT_FALSE(h.log_scale);  // 12 to 48: within two decades
}

}  // namespace
}  // namespace epviz::sweep
