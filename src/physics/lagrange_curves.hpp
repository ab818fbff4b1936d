#pragma once
// The Lagrange top's critical values at a fixed area (docs/math.md §2.6). For
// I = (A, A, C), r = (0, 0, z0), weight P, with n = Ω3 and u = γ3, the
// energy of a state is at least the effective potential
//   V(u) = C n²/2 + (ℓ − C n u)² / (2 A (1 − u²)) + P z0 u,
// and the critical states are the steady precessions (V'(u) = 0, u in (−1, 1)):
//   C² u n² − C ℓ (1 + u²) n + ℓ² u + P z0 A (1 − u²)² = 0,
// whose roots are n = [ℓ(1 + u²) ± (1 − u²) √(ℓ² − 4 A P z0 u)] / (2 C u),
// and the sleeping tops γ = ±e3, n = ±ℓ/C. Every point is a real state's.
#include <vector>

#include "physics/body.hpp"
#include "physics/critical_values.hpp"

namespace epviz::physics::lagrange {

// The state of the steady precession at (u, n): γ = (√(1 − u²), 0, u),
// Ω3 = n and (Ω1, Ω2) along (γ1, γ2) with C0 = area.
InitialState steady_precession(const Body& body, double area, double u, double n);

// The roots n at u of the quadratic above: the larger |n| first (none where
// ℓ² − 4 A P z0 u < 0; one at u = 0, where the larger one leaves to infinity).
std::vector<double> precession_spins(const Body& body, double area, double u);

// The two branches of steady precessions (the larger and the smaller |Ω3| at
// each u) and the two sleeping tops, with energies up to energy_max.
std::vector<CriticalCurve> critical_curves(const Body& body, double area, double energy_max);

}  // namespace epviz::physics::lagrange
