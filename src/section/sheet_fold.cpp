#include "section/sheet_fold.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace epviz::section {
namespace {

// The range of each of n values taken from every crossing; 1 where a value
// does not vary (so that dividing by it leaves the differences, all zero).
template <class Get>
double range_of(const std::vector<PlottedCrossing>& cs, Get get) {
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& c : cs) {
    lo = std::min(lo, get(c));
    hi = std::max(hi, get(c));
  }
  return hi > lo ? hi - lo : 1.0;
}

}  // namespace

FoldMeasure measure_folds(const std::vector<PlottedCrossing>& crossings) {
  FoldMeasure m;
  if (crossings.size() < 2) return m;
  const double sx = range_of(crossings, [](const auto& c) { return c.x; });
  const double sy = range_of(crossings, [](const auto& c) { return c.y; });
  // Omega and gamma each by the largest range of their components: a
  // component the surface holds fixed (gamma3 = 0 up to rounding) has a range
  // of 1e-16 that would turn rounding into distance.
  std::array<double, 6> ss{};
  for (std::size_t i = 0; i < 6; ++i)
    ss[i] = range_of(crossings, [i](const auto& c) { return c.state[i]; });
  for (std::size_t first : {0, 3}) {
    const double widest = std::max({ss[first], ss[first + 1], ss[first + 2]});
    for (std::size_t i = first; i < first + 3; ++i) ss[i] = widest;
  }
  // A grid of cells as wide as "close": a close pair lies in one cell or in
  // two neighbouring ones, so each crossing is compared with its own cell
  // and its neighbours' only (linear in the crossings, not quadratic).
  const auto cell_of = [&](const PlottedCrossing& c) {
    return std::pair<std::int64_t, std::int64_t>{std::int64_t(std::floor(c.x / sx / kCloseInPlot)),
                                                 std::int64_t(std::floor(c.y / sy / kCloseInPlot))};
  };
  const auto key = [](std::int64_t i, std::int64_t j) {
    return std::uint64_t(i) * 0x9E3779B97F4A7C15ull ^ std::uint64_t(j);
  };
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells;
  for (std::size_t n = 0; n < crossings.size(); ++n) {
    const auto [i, j] = cell_of(crossings[n]);
    cells[key(i, j)].push_back(n);
  }
  for (std::size_t a = 0; a < crossings.size(); ++a) {
    const auto [i, j] = cell_of(crossings[a]);
    for (std::int64_t di = -1; di <= 1; ++di)
      for (std::int64_t dj = -1; dj <= 1; ++dj) {
        const auto it = cells.find(key(i + di, j + dj));
        if (it == cells.end()) continue;
        for (const std::size_t b : it->second) {
          if (b <= a) continue;  // each pair once
          const double dx = (crossings[a].x - crossings[b].x) / sx;
          const double dy = (crossings[a].y - crossings[b].y) / sy;
          if (std::hypot(dx, dy) >= kCloseInPlot) continue;
          ++m.close_pairs;
          double d2 = 0.0;
          for (std::size_t k = 0; k < 6; ++k) {
            const double d = (crossings[a].state[k] - crossings[b].state[k]) / ss[k];
            d2 += d * d;
          }
          if (std::sqrt(d2) > kFarInState) ++m.far_pairs;
        }
      }
  }
  return m;
}

}  // namespace epviz::section
