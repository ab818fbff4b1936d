#include "physics/sampled_values.hpp"

#include <cmath>
#include <random>

#include "physics/invariants.hpp"

namespace epviz::physics {
namespace {

// From the generator's bits, so that the values do not depend on the
// standard library's distributions.
double uniform(std::mt19937_64& random, double lo, double hi) {
  return lo + (hi - lo) * double(random() >> 11) * 0x1.0p-53;
}

}  // namespace

std::vector<ValuePoint> sampled_values(Case c, const Body& body, double area, double energy_max,
                                       int count, unsigned long long seed) {
  std::mt19937_64 random(seed);
  // The kinetic energy of a kept state is at most energy_max minus the least
  // potential; its Ω before the move onto the level is drawn from the box
  // that energy allows, and a little beyond (the move changes it).
  const double lowest_potential = -std::abs(body.weight) * body.com.norm();
  const double kinetic = std::max(energy_max - lowest_potential, 1e-12);
  Vector3d half_width;
  for (int i = 0; i < 3; ++i) half_width(i) = 1.5 * std::sqrt(2.0 * kinetic / body.inertia(i));
  std::vector<ValuePoint> values;
  const long tries = 50L * count;
  for (long t = 0; t < tries && long(values.size()) < count; ++t) {
    Vector3d gamma;
    do {
      gamma = Vector3d(uniform(random, -1, 1), uniform(random, -1, 1), uniform(random, -1, 1));
    } while (gamma.norm() < 0.1 || gamma.norm() > 1.0);
    gamma.normalize();
    Vector3d omega;
    for (int i = 0; i < 3; ++i) omega(i) = uniform(random, -half_width(i), half_width(i));
    const Vector3d n = body.inertia.cwiseProduct(gamma);
    omega += (area - omega.dot(n)) / n.squaredNorm() * n;
    const Invariants v = invariants(body, c, omega, gamma);
    if (v.energy <= energy_max && v.extra) values.push_back({v.energy, *v.extra});
  }
  return values;
}

}  // namespace epviz::physics
