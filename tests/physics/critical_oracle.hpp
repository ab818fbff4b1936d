#pragma once
// Test-only: an independent search for critical states of a top's integrals,
// written here without the library's equations or solver, to check the
// bifurcation diagram (physics/critical_values.hpp) against.
//
// A state x = (Ω, γ) is critical on the level C0 = ℓ when a combination of the
// gradients of C0, C1, the fourth integral I and |γ|² vanishes. The search
// fixes one multiplier to 1 (that of C1 or that of I, chosen per start) and
// runs Gauss–Newton with a pseudo-inverse and a central-difference Jacobian on
//   ∇F_lead + a ∇F_u + b ∇F_v + c ∇|γ|² = 0,  C0 = ℓ,  |γ|² = 1
// (8 equations in 9 unknowns); optionally C1 = h and I = k too (10 in 9), to
// ask whether a given value is critical at all.
#include <Eigen/Core>
#include <Eigen/QR>
#include <functional>
#include <optional>
#include <random>
#include <vector>

namespace epviz::physics::test {

using Vector6d = Eigen::Matrix<double, 6, 1>;

// The values and gradients of (C0, C1, I, |γ|²) at x.
struct OracleIntegrals {
  Eigen::Vector4d value;
  Eigen::Matrix<double, 6, 4> gradient;
};
using IntegralsAt = std::function<OracleIntegrals(const Vector6d&)>;

// C0 = Σ I_i Ω_i γ_i, C1 = ½ Σ I_i Ω_i² + P r·γ, |γ|², and the fourth
// integral with its gradient from `fourth`.
inline IntegralsAt top_integrals(Eigen::Vector3d inertia, Eigen::Vector3d pr,
                                 std::function<double(const Vector6d&, Vector6d&)> fourth) {
  return [=](const Vector6d& x) {
    const Eigen::Vector3d w = x.head<3>(), g = x.tail<3>();
    OracleIntegrals f;
    Vector6d grad_i;
    f.value << inertia.cwiseProduct(w).dot(g), 0.5 * inertia.cwiseProduct(w).dot(w) + pr.dot(g),
        fourth(x, grad_i), g.squaredNorm();
    f.gradient.col(0) << inertia.cwiseProduct(g), inertia.cwiseProduct(w);
    f.gradient.col(1) << inertia.cwiseProduct(w), pr;
    f.gradient.col(2) = grad_i;
    f.gradient.col(3) << 0, 0, 0, 2.0 * g;
    return f;
  };
}

// Kovalevskaya's K for I = (2c, 2c, c), r = (a0, 0, 0), weight P (ε = P a0 / c).
inline IntegralsAt kovalevskaya_integrals(double c, double a0, double weight) {
  const double e = weight * a0 / c;
  return top_integrals(Eigen::Vector3d(2 * c, 2 * c, c), Eigen::Vector3d(weight * a0, 0, 0),
                       [e](const Vector6d& x, Vector6d& grad) {
                         const double p = x(0) * x(0) - x(1) * x(1) - e * x(3);
                         const double q = 2 * x(0) * x(1) - e * x(4);
                         grad << 2 * p * 2 * x(0) + 2 * q * 2 * x(1),
                             -2 * p * 2 * x(1) + 2 * q * 2 * x(0), 0, -2 * p * e, -2 * q * e, 0;
                         return p * p + q * q;
                       });
}

// The Lagrange top's Ω3 for I = (a, a, c), r = (0, 0, z0), weight P.
inline IntegralsAt lagrange_integrals(double a, double c, double weight_z0) {
  return top_integrals(Eigen::Vector3d(a, a, c), Eigen::Vector3d(0, 0, weight_z0),
                       [](const Vector6d& x, Vector6d& grad) {
                         grad << 0, 0, 1, 0, 0, 0;
                         return x(2);
                       });
}

struct OracleStart {
  Vector6d x;
  Eigen::Vector3d multipliers;
  int lead = 1;  // 1: C1's multiplier is 1; 2: I's
};

// The residual of the equations above; `value` given: C1 = value(0), I = value(1) too.
inline Eigen::VectorXd oracle_residual(const IntegralsAt& f, double area, int lead,
                                       const std::optional<Eigen::Vector2d>& value,
                                       const Eigen::VectorXd& z) {
  const OracleIntegrals v = f(z.head<6>());
  const int other = lead == 1 ? 2 : 1;
  Eigen::VectorXd r(value ? 10 : 8);
  r.head<6>() = v.gradient.col(lead) + z(6) * v.gradient.col(0) + z(7) * v.gradient.col(other) +
                z(8) * v.gradient.col(3);
  r(6) = v.value(0) - area;
  r(7) = v.value(3) - 1.0;
  if (value) r.tail<2>() << v.value(1) - (*value)(0), v.value(2) - (*value)(1);
  return r;
}

// Gauss–Newton from `start`; the state when the residual falls below 1e-11.
inline std::optional<Vector6d> oracle_search(const IntegralsAt& f, double area,
                                             const OracleStart& start,
                                             const std::optional<Eigen::Vector2d>& value = {}) {
  Eigen::VectorXd z(9);
  z << start.x, start.multipliers;
  const auto residual = [&](const Eigen::VectorXd& y) {
    return oracle_residual(f, area, start.lead, value, y);
  };
  for (int it = 0; it < 200; ++it) {
    const Eigen::VectorXd r = residual(z);
    if (!r.allFinite() || r.norm() > 1e8) return std::nullopt;
    if (r.norm() < 1e-11) return Vector6d(z.head<6>());
    Eigen::MatrixXd j(r.size(), 9);
    for (int i = 0; i < 9; ++i) {
      Eigen::VectorXd up = z, down = z;
      up(i) += 1e-6;
      down(i) -= 1e-6;
      j.col(i) = (residual(up) - residual(down)) / 2e-6;
    }
    Eigen::VectorXd step = j.completeOrthogonalDecomposition().solve(-r);
    if (step.norm() > 1.0) step *= 1.0 / step.norm();  // far from a solution: short steps
    z += step;
  }
  return std::nullopt;
}

inline OracleStart random_oracle_start(std::mt19937_64& random, double omega_max) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  OracleStart s;
  Eigen::Vector3d g;
  do g = Eigen::Vector3d(u(random), u(random), u(random));
  while (g.norm() < 0.1 || g.norm() > 1.0);
  s.x << omega_max * u(random), omega_max * u(random), omega_max * u(random), g.normalized();
  s.multipliers << 2 * u(random), 2 * u(random), 2 * u(random);
  s.lead = u(random) < 0 ? 1 : 2;
  return s;
}

}  // namespace epviz::physics::test
