#include "physics/level_set.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "physics/admissible.hpp"

namespace epviz::physics {

namespace {

constexpr double kPi = 3.14159265358979323846;
// 2 pi (1 - 1/phi): successive multiples never line up, so points spread.
const double kGoldenAngle = kPi * (3.0 - std::sqrt(5.0));
constexpr double kTolerance = 1e-12;

// Residuals of (C0, C1) at (omega, gamma) against the level, each divided by
// max(|target|, the natural magnitude of its terms) as in docs/math.md §1.4,
// so that a level of zero still has a meaningful relative error.
struct Misfit {
  double area = 0.0, energy = 0.0;  // value - target
  double area_scale = 1.0, energy_scale = 1.0;
  bool within(double tol) const {
    return std::abs(area) <= tol * area_scale && std::abs(energy) <= tol * energy_scale;
  }
};

Misfit misfit(const Body& body, const Level& level, const Vector3d& omega, const Vector3d& gamma) {
  const Vector3d m = body.inertia.cwiseProduct(omega);
  const double t = 0.5 * m.dot(omega);
  Misfit f;
  f.area = m.dot(gamma) - level.area;
  f.energy = t + potential(body, gamma) - level.energy;
  f.area_scale = std::max({std::abs(level.area), m.norm() * gamma.norm(), 1e-300});
  f.energy_scale =
      std::max({std::abs(level.energy), t + body.weight * body.com.norm() * gamma.norm(), 1e-300});
  return f;
}

// One Newton step on Omega (gamma fixed) for the two residuals: the least-norm
// correction with gradients I gamma (of C0) and I Omega (of C1). Where the two
// gradients are parallel (Omega along gamma, the bottom of the level) only C0
// is corrected; C1 is then at its minimum over the plane and a first-order
// step cannot move it.
Vector3d newton_step(const Body& body, const Misfit& f, const Vector3d& omega,
                     const Vector3d& gamma) {
  const Vector3d a = body.inertia.cwiseProduct(gamma);
  const Vector3d b = body.inertia.cwiseProduct(omega);
  const double aa = a.dot(a), ab = a.dot(b), bb = b.dot(b);
  const double det = aa * bb - ab * ab;
  if (det <= 1e-12 * aa * bb) return -(f.area / aa) * a;
  const double x = (bb * f.area - ab * f.energy) / det;
  const double y = (aa * f.energy - ab * f.area) / det;
  return -(x * a + y * b);
}

}  // namespace

double potential(const Body& body, const Vector3d& gamma) {
  return body.weight * body.com.dot(gamma);
}

double minimum_kinetic_energy(const Body& body, double area, const Vector3d& gamma) {
  return area * area / (2.0 * gamma.dot(body.inertia.cwiseProduct(gamma)));
}

std::vector<Vector3d> fibonacci_sphere(int n) {
  std::vector<Vector3d> out;
  if (n <= 0) return out;
  out.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    // Equal-area bands in z: the midpoint of the i-th of n.
    const double z = -1.0 + (2.0 * i + 1.0) / n;
    const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = kGoldenAngle * i;
    out.emplace_back(rho * std::cos(phi), rho * std::sin(phi), z);
  }
  return out;
}

LevelStates level_states(const Body& body, const Level& level,
                         const std::vector<Vector3d>& gammas) {
  if (!std::isfinite(level.energy) || !std::isfinite(level.area))
    throw std::invalid_argument("level_states: the level (C1, C0) must be finite");
  LevelStates out;
  for (std::size_t i = 0; i < gammas.size(); ++i) {
    const double norm = gammas[i].norm();
    if (!std::isfinite(norm) || norm == 0.0) {
      out.rejected.push_back({gammas[i], Rejection::invalid_gamma, 0.0});
      continue;
    }
    const Vector3d gamma = gammas[i] / norm;
    const Vector3d n = body.inertia.cwiseProduct(gamma);
    const double q = gamma.dot(n);
    const double budget = level.energy - potential(body, gamma);  // the kinetic energy to reach
    const double floor = minimum_kinetic_energy(body, level.area, gamma);
    const double excess = budget - floor;
    // A level that touches the floor only by round-off still counts.
    const double slack =
        kTolerance * std::max({std::abs(level.energy), floor + std::abs(potential(body, gamma)),
                               body.weight * body.com.norm()});
    if (excess < -slack) {
      out.rejected.push_back({gammas[i], Rejection::below_level, -excess});
      continue;
    }
    // On the plane n.Omega = C0 the kinetic energy is T_min + s^2 u.I u / 2
    // for Omega = Omega0 + s u, n.u = 0: the cross term vanishes because
    // I Omega0 is parallel to n.
    const Vector3d e1 = n.unitOrthogonal();
    const Vector3d e2 = n.normalized().cross(e1);
    const double angle = kGoldenAngle * static_cast<double>(i);
    const Vector3d u = std::cos(angle) * e1 + std::sin(angle) * e2;
    const double s = std::sqrt(2.0 * std::max(0.0, excess) / u.dot(body.inertia.cwiseProduct(u)));
    Vector3d omega = (level.area / q) * gamma + s * u;
    Misfit f = misfit(body, level, omega, gamma);
    for (int k = 0; k < 3 && !f.within(kTolerance / 16); ++k) {
      omega += newton_step(body, f, omega, gamma);
      f = misfit(body, level, omega, gamma);
    }
    if (!f.within(kTolerance)) {
      out.rejected.push_back({gammas[i], Rejection::inaccurate, 0.0});
      continue;
    }
    out.states.push_back({omega, gamma});
  }
  return out;
}

LevelStates level_states(const Body& body, const Level& level, int n) {
  return level_states(body, level, fibonacci_sphere(n));
}

std::vector<Vector3d> fibonacci_cap(const Vector3d& centre, double radius, int n) {
  std::vector<Vector3d> out;
  if (n <= 0) return out;
  const Vector3d c = centre.normalized();
  const Vector3d e1 = c.unitOrthogonal(), e2 = c.cross(e1);
  // Equal areas: 1 - cos(theta) grows linearly with the point's index.
  const double cap = 1.0 - std::cos(std::min(radius, kPi));
  out.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - cap * (i + 0.5) / n;
    const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = kGoldenAngle * i;
    out.push_back(z * c + rho * (std::cos(phi) * e1 + std::sin(phi) * e2));
  }
  return out;
}

LevelStates level_states_about_minimum(const Body& body, const Level& level, int n) {
  const Vector3d centre = minimum_energy(body, level.area).gamma;
  LevelStates best;
  for (double radius = 1.0; radius >= 1e-9; radius /= 4.0) {
    LevelStates cap = level_states(body, level, fibonacci_cap(centre, radius, n));
    if (int(cap.states.size()) >= n) return cap;
    if (cap.states.size() > best.states.size()) best = std::move(cap);
  }
  return best;
}

}  // namespace epviz::physics
