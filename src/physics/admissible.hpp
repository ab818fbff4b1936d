#pragma once
// The admissible region of the (C0, C1) plane (docs/math.md §1.5): for a given
// area constant C0 the energy C1 of any state is at least
//   min over |gamma| = 1 of  V(gamma) + C0^2 / (2 gamma.I gamma),
// and every larger C1 has states (physics/level_set.hpp).
#include "physics/body.hpp"

namespace epviz::physics {

struct EnergyMinimum {
  double energy = 0.0;  // the least C1 at this C0
  Vector3d gamma;       // a unit gamma attaining it (one of several when the body is symmetric)
};

// Numerically: the function above on a dense Fibonacci grid, then a Newton
// descent on the sphere from every grid point that is lowest among its
// neighbours. Throws std::invalid_argument for a non-finite area. The body
// must be valid (positive moments).
EnergyMinimum minimum_energy(const Body& body, double area);

}  // namespace epviz::physics
