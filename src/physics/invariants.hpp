#pragma once
// First integrals of the Euler-Poisson equations and the scales their drifts
// are measured against.
#include <optional>

#include "physics/body.hpp"
#include "physics/cases.hpp"

namespace epviz::physics {

struct Invariants {
  double gamma_norm2 = 0.0;     // |gamma|^2
  double area = 0.0;            // C0 = sum I_i Omega_i gamma_i
  double energy = 0.0;          // C1 = 1/2 sum I_i Omega_i^2 + P r.gamma
  std::optional<double> extra;  // the case's fourth integral
};

Invariants invariants(const Body& body, Case c, const Vector3d& omega, const Vector3d& gamma);

// Relative drift of an invariant is |I(t) - I(0)| / scale, where scale is
// max(|I(0)|, a natural magnitude of its terms) so that an invariant whose value
// is zero (C0 = 0 in Goryachev-Chaplygin, H = 0 for Hess) still has a
// meaningful relative error:
//   |gamma|^2: 1;  C0: |I Omega| |gamma|;  C1: 1/2 sum I_i Omega_i^2 + P |r| |gamma|;
//   extra: sum of the absolute values of its terms at t = 0.
Invariants invariant_scales(const Body& body, Case c, const Vector3d& omega0,
                            const Vector3d& gamma0);

}  // namespace epviz::physics
