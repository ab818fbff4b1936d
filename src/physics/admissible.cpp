#include "physics/admissible.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "physics/level_set.hpp"

namespace epviz::physics {

namespace {

constexpr int kGridPoints = 2000;
// A ring of equal minima (a symmetric body) gives many starts; a few suffice.
constexpr std::size_t kMaxStarts = 64;

// The function minimised: the least energy of a state with this unit gamma.
double floor_energy(const Body& body, double area, const Vector3d& gamma) {
  return potential(body, gamma) + minimum_kinetic_energy(body, area, gamma);
}

// Newton's method on the sphere: the gradient and Hessian of floor_energy in
// the tangent plane at gamma, the step mapped back by normalisation, with
// backtracking so that the energy never rises. Where the Hessian is not
// positive definite (far from a minimum) it steps down the gradient instead.
Vector3d descend(const Body& body, double area, Vector3d gamma) {
  const double c2 = area * area;
  for (int it = 0; it < 100; ++it) {
    const Vector3d n = body.inertia.cwiseProduct(gamma);
    const double q = gamma.dot(n);
    const Vector3d grad = body.weight * body.com - (c2 / (q * q)) * n;
    const Eigen::Matrix3d hess = -(c2 / (q * q)) * Eigen::Matrix3d(body.inertia.asDiagonal()) +
                                 (4.0 * c2 / (q * q * q)) * n * n.transpose();
    Eigen::Matrix<double, 3, 2> e;
    e.col(0) = gamma.unitOrthogonal();
    e.col(1) = gamma.cross(e.col(0));
    const Eigen::Vector2d g = e.transpose() * grad;
    // The sphere's curvature adds -(gamma.grad) to the tangent Hessian.
    const Eigen::Matrix2d h =
        e.transpose() * hess * e - gamma.dot(grad) * Eigen::Matrix2d::Identity();
    Eigen::Vector2d d = -g;
    if (h(0, 0) > 0.0 && h.determinant() > 0.0) d = -h.inverse() * g;
    if (d.norm() > 0.5) d *= 0.5 / d.norm();
    const double e0 = floor_energy(body, area, gamma);
    bool moved = false;
    for (double t = 1.0; t > 1e-12 && !moved; t *= 0.5) {
      const Vector3d cand = (gamma + t * (e * d)).normalized();
      if (floor_energy(body, area, cand) < e0 + 1e-4 * t * g.dot(d)) {
        gamma = cand;
        moved = true;
      }
    }
    if (!moved) break;  // no decrease left above round-off: at the minimum
  }
  return gamma;
}

}  // namespace

EnergyMinimum minimum_energy(const Body& body, double area) {
  if (!std::isfinite(area)) throw std::invalid_argument("minimum_energy: C0 must be finite");
  const std::vector<Vector3d> grid = fibonacci_sphere(kGridPoints);
  std::vector<double> value(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) value[i] = floor_energy(body, area, grid[i]);
  // Grid points lowest within a few spacings: one or more per basin.
  const double radius2 = 6.25 * 4.0 * 3.14159265358979323846 / kGridPoints;
  std::vector<std::size_t> starts;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    bool lowest = true;
    for (std::size_t j = 0; j < grid.size() && lowest; ++j)
      if (j != i && (grid[i] - grid[j]).squaredNorm() < radius2 && value[j] < value[i])
        lowest = false;
    if (lowest) starts.push_back(i);
  }
  std::sort(starts.begin(), starts.end(),
            [&](std::size_t a, std::size_t b) { return value[a] < value[b]; });
  if (starts.size() > kMaxStarts) starts.resize(kMaxStarts);
  EnergyMinimum best{value[starts.front()], grid[starts.front()]};
  for (const std::size_t i : starts) {
    const Vector3d gamma = descend(body, area, grid[i]);
    const double e = floor_energy(body, area, gamma);
    if (e < best.energy) best = {e, gamma};
  }
  return best;
}

}  // namespace epviz::physics
