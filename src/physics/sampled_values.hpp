#pragma once
// The image of a level C0 = area under (C1, fourth integral), sampled: the
// admissible region a bifurcation diagram's curves bound (docs/math.md §2.6).
#include <vector>

#include "physics/body.hpp"
#include "physics/cases.hpp"
#include "physics/critical_values.hpp"

namespace epviz::physics {

// Up to `count` values (C1, integral) of random states with C0 = area and
// C1 <= energy_max: γ uniform on the sphere, Ω uniform in a box large enough
// for that energy, then moved along I γ onto C0 = area; states above
// energy_max are dropped (at most 50 tries per value kept). The same seed
// gives the same values. `c` must have a fourth integral.
std::vector<ValuePoint> sampled_values(Case c, const Body& body, double area, double energy_max,
                                       int count, unsigned long long seed);

}  // namespace epviz::physics
