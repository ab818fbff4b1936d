#include "physics/invariants.hpp"

#include <algorithm>
#include <cmath>

namespace epviz::physics {

Invariants invariants(const Body& body, Case c, const Vector3d& omega, const Vector3d& gamma) {
  Invariants out;
  const Vector3d m = body.inertia.cwiseProduct(omega);
  out.gamma_norm2 = gamma.squaredNorm();
  out.area = m.dot(gamma);
  out.energy = 0.5 * m.dot(omega) + body.weight * body.com.dot(gamma);
  out.extra = extra_integral(c, body, omega, gamma);
  return out;
}

namespace {

// A scale of zero (a body at rest) would make every drift infinite.
double positive(double s) { return s > 0.0 ? s : 1.0; }

}  // namespace

Invariants invariant_scales(const Body& body, Case c, const Vector3d& omega0,
                            const Vector3d& gamma0) {
  const Invariants v = invariants(body, c, omega0, gamma0);
  const Vector3d m = body.inertia.cwiseProduct(omega0);
  Invariants s;
  s.gamma_norm2 = 1.0;
  s.area = positive(std::max(std::abs(v.area), m.norm() * gamma0.norm()));
  s.energy = positive(std::max(
      std::abs(v.energy), 0.5 * m.dot(omega0) + body.weight * body.com.norm() * gamma0.norm()));
  if (const auto x = extra_integral_terms(c, body, omega0, gamma0))
    s.extra = positive(std::max(std::abs(x->value), x->magnitude));
  return s;
}

}  // namespace epviz::physics
