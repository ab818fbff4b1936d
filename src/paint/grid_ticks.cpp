#include "paint/grid_ticks.hpp"

#include <algorithm>
#include <cmath>

#include "paint/figure_common.hpp"

namespace epviz::paint {
namespace {

bool monotone(const std::vector<double>& v) {
  if (v.size() < 2) return false;
  for (double x : v)
    if (!std::isfinite(x)) return false;
  const bool up = v[1] > v[0];
  for (std::size_t k = 1; k < v.size(); ++k)
    if (up ? !(v[k] > v[k - 1]) : !(v[k] < v[k - 1])) return false;
  return true;
}

// The position in cells of plotted value `u` on the plotted cell values `p`
// (monotone): linear within a cell, extrapolated from the outer cells.
double position_of(const std::vector<double>& p, double u) {
  const bool up = p[1] > p[0];
  std::size_t k = 0;
  while (k + 2 < p.size() && (up ? u > p[k + 1] : u < p[k + 1])) ++k;
  return double(k) + (u - p[k]) / (p[k + 1] - p[k]);
}

}  // namespace

bool log_spaced(const std::vector<double>& values) {
  if (values.size() < 3 || !monotone(values)) return false;
  for (double v : values)
    if (!(v > 0.0)) return false;
  // Ratio steps: equal in log10 to within 1 % of a step, and not equal in value.
  const double first = std::log10(values[1] / values[0]);
  for (std::size_t k = 2; k < values.size(); ++k)
    if (std::abs(std::log10(values[k] / values[k - 1]) - first) > 0.01 * std::abs(first))
      return false;
  return std::abs(values[2] - values[1] - (values[1] - values[0])) >
         0.01 * std::abs(values[1] - values[0]);
}

std::vector<GridTick> grid_ticks(const std::vector<double>& values, int max_labels) {
  if (!monotone(values)) return {};
  const bool log = log_spaced(values);
  std::vector<double> p;
  for (double v : values) p.push_back(log ? std::log10(v) : v);
  const double n = double(values.size());
  // The grid's edges in plotted units, half a cell beyond the outer centres.
  const double a = p.front() - 0.5 * (p[1] - p[0]);
  const double b = p.back() + 0.5 * (p.back() - p[p.size() - 2]);
  const double lo = std::min(a, b), hi = std::max(a, b);
  std::vector<Tick> ticks;
  for (const auto& t : axis_ticks(lo, hi, log, std::max(2, max_labels)))
    if (!t.label.empty()) ticks.push_back(t);
  if (log && ticks.size() < 3) {
    // Less than three decades on the grid: 1, 2 and 5 times each power of ten.
    ticks.clear();
    for (double e = std::floor(lo); e <= std::ceil(hi); e += 1.0)
      for (double m : {1.0, 2.0, 5.0}) {
        const double at = e + std::log10(m);
        if (at < lo - 1e-9 || at > hi + 1e-9) continue;
        ticks.push_back({at, print_number(std::pow(10.0, at)), true});
      }
  }
  std::vector<GridTick> out;
  for (const auto& t : ticks) {
    const double pos = position_of(p, t.at);
    if (pos < -0.5 - 1e-9 || pos > n - 0.5 + 1e-9) continue;
    out.push_back({log ? std::pow(10.0, t.at) : t.at, pos, t.label});
  }
  std::sort(out.begin(), out.end(),
            [](const GridTick& x, const GridTick& y) { return x.position < y.position; });
  return out;
}

}  // namespace epviz::paint
