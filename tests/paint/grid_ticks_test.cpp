// Round tick values for a numeric axis of cells (paint/grid_ticks.hpp): each
// tick is a multiple of a 1-2-5 step (or a power of ten on a log-spaced
// grid), lies on the grid, the ticks run one way, and each sits where its
// value falls between the cells' values (checked against the grid's own
// formula, which grid_ticks does not know).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "paint/grid_ticks.hpp"

namespace epviz::paint {
namespace {

std::vector<double> linspace(double a, double b, int n) {
  std::vector<double> v;
  for (int k = 0; k < n; ++k) v.push_back(a + (b - a) * k / (n - 1));
  return v;
}

std::vector<double> geomspace(double a, double b, int n) {
  std::vector<double> v;
  for (int k = 0; k < n; ++k) v.push_back(a * std::pow(b / a, double(k) / (n - 1)));
  return v;
}

// `step` is 1, 2 or 5 times a power of ten.
bool one_two_five(double step) {
  const double m = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
  return std::abs(m - 1.0) < 1e-6 || std::abs(m - 2.0) < 1e-6 || std::abs(m - 5.0) < 1e-6;
}

void expect_round_linear_ticks(const std::vector<double>& v) {
  const int n = int(v.size());
  const double dv = v[1] - v[0];
  const auto ticks = grid_ticks(v, 6);
  ASSERT_GE(ticks.size(), 2u);
  EXPECT_LE(ticks.size(), 10u);
  const double step = std::abs(ticks[1].value - ticks[0].value);
  EXPECT_TRUE(one_two_five(step)) << step;
  for (std::size_t k = 0; k < ticks.size(); ++k) {
    const auto& t = ticks[k];
    EXPECT_NEAR(t.value / step, std::round(t.value / step), 1e-9) << t.value;
    std::string ascii = t.label;  // the minus sign (U+2212) back to a hyphen for stod
    if (ascii.rfind("−", 0) == 0) ascii.replace(0, std::string("−").size(), "-");
    EXPECT_NEAR(std::stod(ascii), t.value, step * 1e-6) << t.label;
    // On the grid, and where the grid's formula puts the value.
    EXPECT_GE(t.position, -0.5);
    EXPECT_LE(t.position, n - 0.5);
    EXPECT_NEAR(t.position, (t.value - v[0]) / dv, 1e-9);
    if (k > 0) {
      EXPECT_GT(t.position, ticks[k - 1].position);
      EXPECT_NEAR(std::abs(t.value - ticks[k - 1].value), step, step * 1e-9);
      EXPECT_EQ(t.value > ticks[k - 1].value, dv > 0) << "ticks do not run with the grid";
    }
  }
}

TEST(GridTicks, RawGridValuesGetRoundTicksAtTheirPositions) {
  expect_round_linear_ticks(linspace(-0.739, 0.912, 24));
  expect_round_linear_ticks(linspace(0.0452, 0.0913, 7));
  expect_round_linear_ticks(linspace(1.5, 10.0, 2));
}

// Rows read top down, so a y axis lists its values from the largest.
TEST(GridTicks, DescendingGrid) { expect_round_linear_ticks(linspace(0.912, -0.739, 24)); }

TEST(GridTicks, LogSpacedGridGetsDecadesAtTheirLogPositions) {
  const auto v = geomspace(0.001, 0.5, 24);
  ASSERT_TRUE(log_spaced(v));
  EXPECT_FALSE(log_spaced(linspace(0.001, 0.5, 24)));
  const auto ticks = grid_ticks(v, 8);
  std::vector<double> values;
  for (const auto& t : ticks) {
    values.push_back(t.value);
    EXPECT_NEAR(t.position, std::log10(t.value / v[0]) / std::log10(v[1] / v[0]), 1e-9);
  }
  ASSERT_EQ(values.size(), 3u);
  EXPECT_NEAR(values[0], 1e-3, 1e-15);
  EXPECT_NEAR(values[1], 1e-2, 1e-15);
  EXPECT_NEAR(values[2], 1e-1, 1e-15);
}

TEST(GridTicks, LogGridWithinADecadeGetsOneTwoFive) {
  const auto v = geomspace(1.0, 6.0, 5);
  std::vector<std::string> labels;
  for (const auto& t : grid_ticks(v, 8)) {
    labels.push_back(t.label);
    EXPECT_NEAR(t.position, std::log10(t.value) / std::log10(v[1]), 1e-9);
  }
  EXPECT_EQ(labels, (std::vector<std::string>{"1", "2", "5"}));
}

// Small values in print: powers of ten in superscripts, not "2e-05".
TEST(GridTicks, SmallOneTwoFiveInPowersOfTen) {
  std::vector<std::string> labels;
  for (const auto& t : grid_ticks(geomspace(1e-5, 6e-5, 5), 8)) labels.push_back(t.label);
  EXPECT_EQ(labels, (std::vector<std::string>{"10⁻⁵", "2×10⁻⁵", "5×10⁻⁵"}));
}

// Negative values with the minus sign (U+2212), never a hyphen.
TEST(GridTicks, NegativeLabelsUseTheMinusSign) {
  int negative = 0;
  for (const auto& t : grid_ticks(linspace(-0.739, 0.912, 24), 6)) {
    EXPECT_EQ(t.label.find('-'), std::string::npos) << t.label;
    if (t.value < 0.0) {
      ++negative;
      EXPECT_EQ(t.label.rfind("−", 0), 0u) << t.label;
    }
  }
  EXPECT_GE(negative, 1);
}

// Uneven cells: linear within each cell.
TEST(GridTicks, UnevenGridInterpolatesWithinTheCell) {
  const std::vector<double> v{0.0, 0.1, 0.5, 1.0};
  for (const auto& t : grid_ticks(v, 5)) {
    const double expected = t.value <= 0.1   ? t.value / 0.1
                            : t.value <= 0.5 ? 1.0 + (t.value - 0.1) / 0.4
                                             : 2.0 + (t.value - 0.5) / 0.5;
    EXPECT_NEAR(t.position, expected, 1e-9) << t.value;
  }
}

TEST(GridTicks, NoTicksForWhatIsNotAMonotoneGrid) {
  EXPECT_TRUE(grid_ticks({}, 5).empty());
  EXPECT_TRUE(grid_ticks({1.0}, 5).empty());
  EXPECT_TRUE(grid_ticks({0.0, 1.0, 0.5}, 5).empty());
  EXPECT_TRUE(grid_ticks({0.0, NAN, 1.0}, 5).empty());
}

}  // namespace
}  // namespace epviz::paint
