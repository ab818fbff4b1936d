#include "sim/section_chart_inverse.hpp"

#include <Eigen/Geometry>  // cross()
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace epviz::sim {
namespace {

bool is_gamma(StateComponent c) { return int(c) >= 3; }
int axis_of(StateComponent c) { return int(c) % 3; }

struct ChartAxes {
  int k;            // the surface's gamma_k = c
  int i;            // the plotted gamma_i
  int m;            // the sheet's gamma_m
  bool gamma_on_x;  // coords = (gamma_i, Omega_k), else (Omega_k, gamma_i)
};

std::optional<ChartAxes> chart_axes(const SectionSurface& s,
                                    const std::array<StateComponent, 2>& coords) {
  if (s.angle || !is_gamma(s.function) || !(std::abs(s.value) < 1.0)) return std::nullopt;
  const int k = axis_of(s.function);
  const bool gamma_on_x = is_gamma(coords[0]);
  const StateComponent g = gamma_on_x ? coords[0] : coords[1];
  const StateComponent w = gamma_on_x ? coords[1] : coords[0];
  if (!is_gamma(g) || is_gamma(w) || axis_of(w) != k || axis_of(g) == k) return std::nullopt;
  const int i = axis_of(g);
  return ChartAxes{k, i, 3 - k - i, gamma_on_x};
}

bool crosses_as_asked(CrossingDirection d, double rate) {
  switch (d) {
    case CrossingDirection::upward: return rate > 0.0;
    case CrossingDirection::downward: return rate < 0.0;
    case CrossingDirection::both: return rate != 0.0;
  }
  return false;
}

}  // namespace

std::optional<StateComponent> chart_sheet_component(const SectionSurface& surface,
                                                    const std::array<StateComponent, 2>& coords) {
  const auto axes = chart_axes(surface, coords);
  if (!axes) return std::nullopt;
  return StateComponent(3 + axes->m);
}

ChartPreimage section_states_at(const physics::Body& body, const physics::Level& level,
                                const SectionSurface& surface,
                                const std::array<StateComponent, 2>& coords, double x, double y,
                                int sheet) {
  const auto axes = chart_axes(surface, coords);
  if (!axes)
    throw std::invalid_argument(
        "section_states_at: the chart must be a surface gamma_k = c (|c| < 1) at (gamma_i, "
        "omega_k)");
  const auto [k, i, m, gamma_on_x] = *axes;
  const double c = surface.value;
  const double gi = gamma_on_x ? x : y;
  const double wk = gamma_on_x ? y : x;
  const Eigen::Vector3d& I = body.inertia;
  const std::string gi_name(symbol(StateComponent(3 + i)));
  const std::string gk_name(symbol(surface.function));

  ChartPreimage out;
  const double rest = 1.0 - c * c - gi * gi;
  if (!std::isfinite(rest) || !std::isfinite(wk) || rest < 0.0) {
    char why[160];
    std::snprintf(why, sizeof why, "no unit γ has %s = %.4g on %s = %g", gi_name.c_str(), gi,
                  gk_name.c_str(), c);
    out.why_none = why;
    return out;
  }
  double shortfall = -1.0;  // the least energy a sheet lacks, when every sheet lacks some
  bool other_direction = false;
  std::vector<std::pair<double, physics::InitialState>> found;  // |rate|, state
  for (const int sign : {+1, -1}) {
    if (sheet != 0 && sign != sheet && rest > 0.0) continue;
    if (sign < 0 && rest == 0.0) continue;  // on the fold: one sheet
    Eigen::Vector3d gamma;
    gamma[k] = c;
    gamma[i] = gi;
    gamma[m] = sign * std::sqrt(rest);
    // C0 = I.Omega.gamma and C1 = 1/2 I.Omega^2 + P r.gamma with Omega_k
    // known, in the scaled unknowns u = (sqrt(I_i) Omega_i, sqrt(I_m) Omega_m):
    // n.u = a (a line) and |u|^2 = q (a circle).
    const double a = level.area - I[k] * wk * c;
    const double q = 2.0 * (level.energy - body.weight * body.com.dot(gamma)) - I[k] * wk * wk;
    const Eigen::Vector2d n(std::sqrt(I[i]) * gamma[i], std::sqrt(I[m]) * gamma[m]);
    const double nn = n.squaredNorm();
    if (!(nn > 0.0)) continue;  // gamma = +-e_k: excluded by |c| < 1
    const double s2 = q - a * a / nn;
    if (s2 < 0.0) {
      // Twice the kinetic energy lacking: half of it is the energy's shortfall.
      shortfall = shortfall < 0.0 ? -0.5 * s2 : std::min(shortfall, -0.5 * s2);
      continue;
    }
    const Eigen::Vector2d foot = (a / nn) * n;
    const Eigen::Vector2d along = Eigen::Vector2d(-n.y(), n.x()) / std::sqrt(nn);
    const double s = std::sqrt(s2);
    for (const double side : {+1.0, -1.0}) {
      if (side < 0.0 && s == 0.0) break;  // a tangent point: one state
      const Eigen::Vector2d u = foot + side * s * along;
      Eigen::Vector3d omega;
      omega[k] = wk;
      omega[i] = u.x() / std::sqrt(I[i]);
      omega[m] = u.y() / std::sqrt(I[m]);
      const double rate = gamma.cross(omega)[k];
      if (!crosses_as_asked(surface.direction, rate)) {
        other_direction = true;
        continue;
      }
      found.push_back({std::abs(rate), physics::InitialState{omega, gamma}});
    }
  }
  std::stable_sort(found.begin(), found.end(),
                   [](const auto& p, const auto& q) { return p.first > q.first; });
  for (auto& f : found) out.states.push_back(f.second);
  if (!out.states.empty()) return out;
  char why[200];
  if (other_direction)
    std::snprintf(why, sizeof why, "the level's orbits cross %s = %g there only %s",
                  gk_name.c_str(), c,
                  surface.direction == CrossingDirection::upward ? "downward (or tangent)"
                                                                 : "upward (or tangent)");
  else if (shortfall >= 0.0)
    std::snprintf(why, sizeof why,
                  "no state of the level C1 = %.6g, C0 = %.6g there: it lacks %.3g of energy",
                  level.energy, level.area, shortfall);
  else
    std::snprintf(why, sizeof why, "no state of the level there");
  out.why_none = why;
  return out;
}

}  // namespace epviz::sim
