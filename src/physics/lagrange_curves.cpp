#include "physics/lagrange_curves.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "physics/invariants.hpp"

namespace epviz::physics::lagrange {
namespace {

// Values of u in (−1, 1): dense enough that the drawn curve is smooth where
// the energy climbs steeply (the larger root near u = 0).
constexpr int kTiltSteps = 4000;

ValuePoint value_of(const Body& body, double area, double u, double n) {
  const InitialState s = steady_precession(body, area, u, n);
  return {invariants(body, Case::lagrange, s.omega, s.gamma).energy, n};
}

// Appends p, or a break (NaN) where p is not shown.
void append(std::vector<ValuePoint>& points, ValuePoint p, double energy_max) {
  if (std::isfinite(p.energy) && p.energy <= energy_max) {
    points.push_back(p);
  } else if (!points.empty() && !std::isnan(points.back().energy)) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    points.push_back({nan, nan});
  }
}

}  // namespace

InitialState steady_precession(const Body& body, double area, double u, double n) {
  const double a = body.inertia.x(), c = body.inertia.z();
  const double sine = std::sqrt(std::max(0.0, 1.0 - u * u));
  // A (Ω1 γ1 + Ω2 γ2) = ℓ − C n u with (Ω1, Ω2) along (γ1, γ2) = (sin, 0).
  const double along = (area - c * n * u) / (a * sine);
  return {Vector3d(along, 0.0, n), Vector3d(sine, 0.0, u)};
}

std::vector<double> precession_spins(const Body& body, double area, double u) {
  const double a = body.inertia.x(), c = body.inertia.z();
  const double pz = body.weight * body.com.z();
  double discriminant = area * area - 4.0 * a * pz * u;
  // At the fold u = ℓ²/(4 A P z0), where the branches meet, round-off may leave it below zero.
  if (discriminant < 0.0 && discriminant > -1e-12 * (area * area + std::abs(4.0 * a * pz)))
    discriminant = 0.0;
  if (discriminant < 0.0) return {};
  const double v = 1.0 - u * u;
  // Both roots without cancellation: the larger from the sum whose terms
  // share a sign, the smaller from the product of the roots.
  const double sum = area * (1.0 + u * u) + std::copysign(v * std::sqrt(discriminant), area);
  const double product = area * area * u + pz * a * v * v;  // times C² u: the product's numerator
  std::vector<double> n;
  if (u != 0.0 && sum != 0.0) n.push_back(sum / (2.0 * c * u));
  if (sum != 0.0) n.push_back(2.0 * product / (c * sum));
  return n;
}

std::vector<CriticalCurve> critical_curves(const Body& body, double area, double energy_max) {
  CriticalCurve fast{"precession_large", "steady precessions, larger |Ω₃|", {}};
  CriticalCurve slow{"precession_small", "steady precessions, smaller |Ω₃|", {}};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Denser towards u = ±1, where the branches meet the sleeping tops, and the
  // fold where they meet each other (P z0 > 0, ℓ² < 4 A P z0) itself.
  std::vector<double> tilts;
  for (int i = 1; i < kTiltSteps; ++i)
    tilts.push_back(-std::cos(std::numbers::pi * i / kTiltSteps));
  const double pz0 = body.weight * body.com.z();
  if (pz0 != 0.0) {
    const double fold = area * area / (4.0 * body.inertia.x() * pz0);
    if (fold > -1.0 && fold < 1.0)
      tilts.insert(std::upper_bound(tilts.begin(), tilts.end(), fold), fold);
  }
  for (const double u : tilts) {
    const auto n = precession_spins(body, area, u);
    const bool both = n.size() == 2;
    append(fast.points, both ? value_of(body, area, u, n[0]) : ValuePoint{nan, nan}, energy_max);
    append(slow.points, n.empty() ? ValuePoint{nan, nan} : value_of(body, area, u, n.back()),
           energy_max);
  }
  std::vector<CriticalCurve> curves{fast, slow};
  const double c = body.inertia.z();
  for (const double u : {1.0, -1.0}) {
    const double n = area / (c * u);
    const ValuePoint top{0.5 * c * n * n + pz0 * u, n};
    if (top.energy > energy_max) continue;
    curves.push_back({u > 0 ? "sleeping_up" : "sleeping_down",
                      u > 0 ? "sleeping top, γ₃ = 1" : "sleeping top, γ₃ = −1",
                      {top},
                      true});
  }
  for (auto& curve : curves)
    if (!curve.points.empty() && std::isnan(curve.points.back().energy)) curve.points.pop_back();
  return curves;
}

}  // namespace epviz::physics::lagrange
