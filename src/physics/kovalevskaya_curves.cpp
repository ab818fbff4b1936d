#include "physics/kovalevskaya_curves.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <random>

#include "physics/kovalevskaya_critical_states.hpp"

namespace epviz::physics::kovalevskaya {
namespace {

// Energies sampled between the least energy and the largest shown.
constexpr int kEnergySteps = 400;
// Random starts are tried at every kDiscoveryStride-th point a continuation
// has not reached, kRandomStarts of them: they find an attained part, and the
// continuation from the found state fills the rest of it in both directions.
constexpr int kDiscoveryStride = 3;
constexpr int kRandomStarts = 6;

double energy_at(double area, double s) { return s + area * area / (4.0 * s * s); }

// The s in (lo, hi) with energy_at(s) = h, energy_at monotone there and
// taking h between the ends: bisection to the last bit.
double bisect(double area, double h, double lo, double hi) {
  const bool rising = energy_at(area, lo) < energy_at(area, hi);
  for (int i = 0; i < 200 && lo < hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    ((energy_at(area, mid) < h) == rising ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

std::vector<double> energy_grid(double lo, double hi) {
  std::vector<double> h(kEnergySteps);
  for (int i = 0; i < kEnergySteps; ++i) h[i] = lo + (hi - lo) * i / (kEnergySteps - 1);
  return h;
}

// The points of `candidate` real critical states attain, a NaN point in place
// of every run of the others.
std::vector<ValuePoint> attained_part(CriticalKind kind, double area,
                                      const std::vector<ValuePoint>& candidate,
                                      std::mt19937_64& random) {
  const std::size_t n = candidate.size();
  std::vector<std::optional<Eigen::VectorXd>> found(n);
  const auto solve = [&](std::size_t i, const std::vector<Eigen::VectorXd>& starts) {
    return solve_critical_state(kind, area, candidate[i].energy, candidate[i].integral, starts);
  };
  int unreached = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0 && found[i - 1]) found[i] = solve(i, {*found[i - 1]});
    if (!found[i] && unreached++ % kDiscoveryStride == 0)
      found[i] = solve(i, random_starts(kind, area, candidate[i].energy, kRandomStarts, random));
    if (found[i]) unreached = 0;
  }
  // Backwards from every attained part, over the points before it that the
  // forward pass reached with neither continuation nor random starts.
  for (std::size_t i = n; i-- > 1;)
    if (found[i] && !found[i - 1]) found[i - 1] = solve(i - 1, {*found[i]});
  std::vector<ValuePoint> kept;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < n; ++i) {
    if (found[i])
      kept.push_back(candidate[i]);
    else if (!kept.empty() && !std::isnan(kept.back().energy))
      kept.push_back({nan, nan});
  }
  if (!kept.empty() && std::isnan(kept.back().energy)) kept.pop_back();
  return kept;
}

}  // namespace

ValuePoint parametric_point(double area, double s) {
  const double l2 = area * area;
  return {energy_at(area, s), 1.0 - l2 / (2.0 * s) + l2 * l2 / (16.0 * s * s * s * s)};
}

std::vector<double> parametric_roots(double area, double energy) {
  if (area == 0.0) return {energy};  // s = h (h = 0 is no point of the curve)
  std::vector<double> roots;
  // s < 0: energy_at rises from −∞ to +∞.
  double lo = std::min(energy, 0.0) - 1.0 - area * area / 4.0, hi = -1.0;
  while (energy_at(area, hi) <= energy) hi *= 0.5;
  roots.push_back(bisect(area, energy, lo, hi));
  // s > 0: falls from +∞ to the cusp at s*, then rises again.
  const double cusp = std::cbrt(area * area / 2.0);
  if (energy < energy_at(area, cusp)) return roots;
  lo = cusp;
  while (energy_at(area, lo) <= energy) lo *= 0.5;
  roots.push_back(bisect(area, energy, lo, cusp));
  roots.push_back(bisect(area, energy, cusp, std::max(energy, cusp) + 1.0));
  return roots;
}

std::vector<CriticalCurve> critical_curves(double area, double energy_min, double energy_max,
                                           unsigned long long seed) {
  std::mt19937_64 random(seed);
  const std::vector<double> grid = energy_grid(energy_min, energy_max);
  const double l2 = area * area;
  std::vector<ValuePoint> class1, class2, negative, positive;
  for (const double h : grid) {
    class1.push_back({h, 0.0});
    class2.push_back({h, (h - l2 / 2.0) * (h - l2 / 2.0)});
    negative.push_back(parametric_point(area, parametric_roots(area, h).front()));
  }
  if (area == 0.0) {
    // The limit ℓ → 0: the branches become the line k = 1 (s = h), and both
    // their parts near s = 0 (s ≈ ∓ℓ / (2√h)) the parabola k = 1 + h², h ≥ 0,
    // drawn once, as the continuation of s < 0 past h = 0.
    negative.clear();
    for (const double h : grid) negative.push_back({h, h < 0.0 ? 1.0 : 1.0 + h * h});
    for (const double h : grid)
      if (h > 0.0) positive.push_back({h, 1.0});
  } else {
    // Along the branch: down the part s < s* towards the cusp, then up the part s > s*.
    const double cusp = std::cbrt(l2 / 2.0);
    std::vector<ValuePoint> rising;
    for (auto h = grid.rbegin(); h != grid.rend(); ++h) {
      const auto roots = parametric_roots(area, *h);
      if (roots.size() < 3) continue;
      positive.push_back(parametric_point(area, roots[1]));
      rising.insert(rising.begin(), parametric_point(area, roots[2]));
    }
    const ValuePoint tip = parametric_point(area, cusp);
    if (tip.energy >= energy_min && tip.energy <= energy_max) positive.push_back(tip);
    positive.insert(positive.end(), rising.begin(), rising.end());
  }
  std::vector<CriticalCurve> curves;
  curves.push_back(
      {"class_I", "class I: k = 0", attained_part(CriticalKind::k_zero, area, class1, random)});
  curves.push_back({"class_II", "class II: k = (h − ℓ²/2)²",
                    attained_part(CriticalKind::multipliers, area, class2, random)});
  curves.push_back({"s_negative", "s < 0: h = s + ℓ²/4s², k = 1 − ℓ²/2s + ℓ⁴/16s⁴",
                    attained_part(CriticalKind::multipliers, area, negative, random)});
  curves.push_back({"s_positive", "s > 0: the same curve",
                    attained_part(CriticalKind::multipliers, area, positive, random)});
  return curves;
}

}  // namespace epviz::physics::kovalevskaya
