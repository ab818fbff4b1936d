#include "physics/critical_values.hpp"

#include <cmath>

#include "physics/admissible.hpp"
#include "physics/format.hpp"
#include "physics/kovalevskaya_curves.hpp"
#include "physics/lagrange_curves.hpp"
#include "physics/sampled_values.hpp"

namespace epviz::physics {
namespace {

// How a Kovalevskaya body I = (2c, 2c, c), r = (a0, 0, 0), weight P scales to
// the normalised one (ε = 1): with ε = |P a0| / c, its C1 is c ε h̃, its C0
// c √ε ℓ̃ and its K ε² k̃ (Ω = √ε Ω̃; a0 < 0 is the normalised body turned
// half a turn about axis 3, which leaves C0 and K as they are).
struct KovalevskayaScale {
  double energy, area, integral;
};

// The largest |C0| of the normalised Kovalevskaya body drawn.
constexpr double kMaxNormalisedArea = 8.0;

KovalevskayaScale kovalevskaya_scale(const Body& body) {
  const double c = body.inertia.z();
  const double eps = std::abs(body.weight * body.com.x()) / c;
  return {c * eps, c * std::sqrt(eps), eps * eps};
}

// Far enough past the last feature of the diagram that every curve shows its
// shape: the cusp of the parametric curve and class II's touching k = 0
// (Kovalevskaya, normalised), the upper sleeping top (Lagrange).
double default_energy_max(const DiagramRequest& r, double energy_min) {
  if (r.case_id == Case::kovalevskaya) {
    const KovalevskayaScale scale = kovalevskaya_scale(r.body);
    const double l = r.area / scale.area;
    const double cusp =
        l == 0.0 ? 0.0 : kovalevskaya::parametric_point(l, std::cbrt(l * l / 2.0)).energy;
    return scale.energy * (std::max({cusp, l * l / 2.0, energy_min / scale.energy}) + 2.0);
  }
  const double c = r.body.inertia.z(), pz = std::abs(r.body.weight * r.body.com.z());
  const double top = std::max(0.5 * r.area * r.area / c + pz, energy_min);
  return top + 0.5 * (top - energy_min) + std::max(pz, 1.0);
}

}  // namespace

double check_diagram_request(const DiagramRequest& r) {
  if (r.case_id != Case::kovalevskaya && r.case_id != Case::lagrange)
    throw InvalidInput("case", "'" + case_name(r.case_id) +
                                   "' has no bifurcation diagram here (allowed: kovalevskaya, "
                                   "lagrange)");
  validate_body(r.body, false);
  if (auto broken = broken_condition(r.case_id, r.body, preset(r.case_id).initial))
    throw InvalidInput("body", *broken);
  if (r.case_id == Case::kovalevskaya && r.body.weight * r.body.com.x() == 0.0)
    throw InvalidInput("body",
                       "kovalevskaya with P a0 = 0 is a torque-free symmetric top (K = (Omega1^2 + "
                       "Omega2^2)^2): no diagram; needs P != 0 and a0 != 0");
  if (!std::isfinite(r.area))
    throw InvalidInput("area", "C0 must be a finite number; got " + detail::num(r.area));
  if (r.case_id == Case::kovalevskaya) {
    // Past this the search for critical states loses curves that real states
    // attain (tests/physics/critical_values_test.cpp checks it up to here).
    const double limit = kMaxNormalisedArea * kovalevskaya_scale(r.body).area;
    if (std::abs(r.area) > limit)
      throw InvalidInput("area", "the kovalevskaya diagram is computed for |C0| up to " +
                                     detail::approx(limit) + " (8 I3 sqrt(|P a0| / I3)); got " +
                                     detail::num(r.area));
  }
  const double energy_min = minimum_energy(r.body, r.area).energy;
  if (r.energy_max && !(std::isfinite(*r.energy_max) && *r.energy_max > energy_min))
    throw InvalidInput(
        "energy_max",
        "must be a finite number above the least energy C1 = " + detail::approx(energy_min) +
            " at C0 = " + detail::num(r.area) + "; got " + detail::num(*r.energy_max));
  return energy_min;
}

BifurcationDiagram bifurcation_diagram(const DiagramRequest& r) {
  BifurcationDiagram d;
  d.energy_min = check_diagram_request(r);
  d.energy_max = r.energy_max.value_or(default_energy_max(r, d.energy_min));
  if (r.case_id == Case::kovalevskaya) {
    const KovalevskayaScale scale = kovalevskaya_scale(r.body);
    d.curves = kovalevskaya::critical_curves(r.area / scale.area, d.energy_min / scale.energy,
                                             d.energy_max / scale.energy, r.seed);
    for (auto& curve : d.curves)
      for (auto& p : curve.points) p = {p.energy * scale.energy, p.integral * scale.integral};
  } else {
    d.curves = lagrange::critical_curves(r.body, r.area, d.energy_max);
  }
  d.sampled = sampled_values(r.case_id, r.body, r.area, d.energy_max, r.samples, r.seed);
  return d;
}

}  // namespace epviz::physics
