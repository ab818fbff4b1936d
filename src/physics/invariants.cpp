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

// Sum of the absolute values of the terms of the case's extra integral.
double extra_terms(Case c, const Body& body, const Vector3d& w, const Vector3d& g) {
  const Vector3d& I = body.inertia;
  const double P = body.weight, a0 = body.com.x(), c0 = body.com.z();
  switch (c) {
    case Case::euler: return I.cwiseProduct(w).squaredNorm();
    case Case::lagrange:
      // Omega3 alone: measured against |Omega| so that Omega3 = 0 still has a scale.
      return w.norm();
    case Case::kovalevskaya: {
      const double k = std::abs(P * a0 / I.z());
      const double x = w.x() * w.x() + w.y() * w.y() + k * std::abs(g.x());
      const double y = 2.0 * std::abs(w.x() * w.y()) + k * std::abs(g.y());
      return x * x + y * y;
    }
    case Case::goryachev_chaplygin:
      return std::abs(w.z()) * (w.x() * w.x() + w.y() * w.y()) +
             std::abs(P * a0 / I.z() * w.x() * g.z());
    case Case::hess: return std::abs(I.x() * a0 * w.x()) + std::abs(I.z() * c0 * w.z());
    case Case::custom:
    case Case::generic: break;
  }
  return 0.0;
}

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
  if (v.extra)
    s.extra = positive(std::max(std::abs(*v.extra), extra_terms(c, body, omega0, gamma0)));
  return s;
}

}  // namespace epviz::physics
