#pragma once
// Real critical states of the Kovalevskaya top, found numerically: what
// decides which parts of the closed-form critical curves real motions attain
// (docs/math.md §2.6). Written for the normalised body I = (2, 2, 1),
// r = (1, 0, 0), P = 1 (ε = 1), to which every body of the case scales
// (physics/critical_values.cpp).
//
// A state x = (Ω, γ) is critical for the integrals F = (C0, C1, K, |γ|²) when
// their gradients are dependent: α∇C0 + β∇C1 + κ∇K + δ∇|γ|² = 0 for some
// unit multipliers (α, β, κ, δ). A value (h, k) at area ℓ is attained when
// some x with C0 = ℓ, C1 = h, K = k, |γ|² = 1 is critical: 11 equations in
// the 10 unknowns (x, multipliers), solvable only on the critical curves.
// On K = 0 every state is critical (K is a sum of two squares X² + Y², so
// ∇K = 0 there), and the value is attained when C0 = ℓ, C1 = h, X = Y = 0,
// |γ|² = 1 has a solution: 5 regular equations in 6 unknowns.
#include <Eigen/Core>
#include <optional>
#include <random>
#include <vector>

namespace epviz::physics::kovalevskaya {

enum class CriticalKind {
  k_zero,       // K = 0, unknowns x (6 numbers)
  multipliers,  // any k, unknowns x and the multipliers (10 numbers)
};

// The largest residual of the equations above (at unit scale) for which the
// state is taken as a solution: round-off is ~1e-15, a point off the curves
// leaves ~1e-4 or more.
inline constexpr double kAttainedResidual = 1e-10;

// A solution z of the equations for (energy, k) at `area`, from the first of
// `starts` that converges (each a z of the kind's size), or nullopt.
std::optional<Eigen::VectorXd> solve_critical_state(CriticalKind kind, double area, double energy,
                                                    double k,
                                                    const std::vector<Eigen::VectorXd>& starts);

// `count` starting points on the level (C0, C1) = (area, energy): states of
// the level on random γ (physics/level_set.hpp), with the multipliers that
// come closest to making the gradients dependent there. Fewer (or none) where
// few random γ carry a state of the level.
std::vector<Eigen::VectorXd> random_starts(CriticalKind kind, double area, double energy, int count,
                                           std::mt19937_64& random);

}  // namespace epviz::physics::kovalevskaya
