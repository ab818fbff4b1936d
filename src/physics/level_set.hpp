#pragma once
// Initial states on a common level of the energy C1 and the area integral C0
// (docs/math.md §1.5): the starting points of Poincaré sections and of
// energy-momentum maps.
#include <vector>

#include "physics/body.hpp"

namespace epviz::physics {

// A level of the two integrals every body has (docs/math.md (1.4), (1.5)).
struct Level {
  double energy = 0.0;  // C1
  double area = 0.0;    // C0
};

// Why a gamma carries no state of the level.
enum class Rejection {
  below_level,    // C1 - V(gamma) < T_min(gamma): every Omega has too much energy
  invalid_gamma,  // zero or not finite: no direction
  inaccurate,     // the construction missed the integrals by more than 1e-12
};

struct RejectedGamma {
  Vector3d gamma;  // as given, before normalisation
  Rejection why = Rejection::below_level;
  // For below_level: T_min(gamma) - (C1 - V(gamma)) > 0, the energy lacking.
  double shortfall = 0.0;
};

struct LevelStates {
  std::vector<InitialState> states;     // |gamma| = 1, C1 and C0 to 1e-12
  std::vector<RejectedGamma> rejected;  // every other gamma, in the order given
};

// The potential V(gamma) = P r.gamma (the second term of C1).
double potential(const Body& body, const Vector3d& gamma);

// The least kinetic energy of an Omega with I Omega . gamma = area:
// area^2 / (2 gamma.I gamma), at Omega = area gamma / (gamma.I gamma).
double minimum_kinetic_energy(const Body& body, double area, const Vector3d& gamma);

// n points spread evenly over the unit sphere (a Fibonacci spiral from the
// south pole to the north pole); empty for n <= 0.
std::vector<Vector3d> fibonacci_sphere(int n);

// One state of `level` for each gamma that admits one (gammas are normalised
// first). The i-th state's Omega leaves the kinetic-energy minimiser along the
// direction at angle i times the golden angle in the plane I Omega . gamma = C0,
// so that states on nearby gammas differ. Throws std::invalid_argument for a
// non-finite level. The body must be valid (positive moments).
LevelStates level_states(const Body& body, const Level& level, const std::vector<Vector3d>& gammas);

// The same over fibonacci_sphere(n): up to n states.
LevelStates level_states(const Body& body, const Level& level, int n);

// n points spread evenly by area over the cap of angular radius `radius`
// (radians, at most pi) about the unit vector `centre` (a Fibonacci spiral
// from the centre outwards); empty for n <= 0.
std::vector<Vector3d> fibonacci_cap(const Vector3d& centre, double radius, int n);

// States of a level close to the least energy at its area, where only a
// small cap of directions about the minimiser (physics/admissible.hpp)
// carries states and a grid over the whole sphere meets none: caps of radius
// 1, 1/4, 1/16, ... down to 1e-9 radians about the minimiser, n directions
// each, and the states of the widest cap where n directions carry one (else
// of the cap where most do). Empty below the least energy.
LevelStates level_states_about_minimum(const Body& body, const Level& level, int n);

}  // namespace epviz::physics
