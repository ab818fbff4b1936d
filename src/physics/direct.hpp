#pragma once
// The Euler-Poisson equations in their direct form (docs/math.md §1.2, eqs. 1.1, 1.2):
// state (Omega, gamma), 6 dimensions, plus the exact sub-flows of the
// Lie-Poisson splitting H = T1 + T2 + T3 + V.
#include <Eigen/Core>
#include <cmath>

#include "physics/body.hpp"

namespace epviz::physics {

// The Euler equations (1.1): Omega' = I^-1 ((I Omega) x Omega + gamma x (P r)).
// Shared by every formulation; `inv_inertia` = 1/I_i, `pr` = P r.
[[gnu::always_inline]] inline Vector3d euler_omega_dot(const Vector3d& inertia,
                                                       const Vector3d& inv_inertia,
                                                       const Vector3d& pr, const Vector3d& w,
                                                       const Vector3d& g) {
  return Vector3d(((inertia.y() - inertia.z()) * w.y() * w.z() + g.y() * pr.z() - g.z() * pr.y()) *
                      inv_inertia.x(),
                  ((inertia.z() - inertia.x()) * w.z() * w.x() + g.z() * pr.x() - g.x() * pr.z()) *
                      inv_inertia.y(),
                  ((inertia.x() - inertia.y()) * w.x() * w.y() + g.x() * pr.y() - g.y() * pr.x()) *
                      inv_inertia.z());
}

class DirectSystem {
 public:
  static constexpr int dim = 6;
  using State = Eigen::Matrix<double, 6, 1>;
  static constexpr const char* name = "direct";
  static constexpr int n_flows = 4;

  explicit DirectSystem(const Body& body)
      : inertia_(body.inertia),
        inv_inertia_(body.inertia.cwiseInverse()),
        pr_(body.weight * body.com) {}

  // x = (Omega, gamma); dxdt = (Omega', gamma x Omega).
  [[gnu::always_inline]] void rhs(double /*t*/, const State& x, State& dxdt) const {
    const Vector3d w = x.head<3>();
    const Vector3d g = x.tail<3>();
    dxdt.head<3>() = euler_omega_dot(inertia_, inv_inertia_, pr_, w, g);
    dxdt[3] = w.z() * g.y() - w.y() * g.z();
    dxdt[4] = w.x() * g.z() - w.z() * g.x();
    dxdt[5] = w.y() * g.x() - w.x() * g.y();
  }

  static State pack(const InitialState& s) {
    State x;
    x << s.omega, s.gamma;
    return x;
  }
  Vector3d omega(const State& x) const { return x.head<3>(); }
  Vector3d gamma(const State& x) const { return x.tail<3>(); }

  // Exact sub-flows for Strang splitting, advancing x by time h:
  //   i = 0: gravity kick, Omega += h I^-1 (gamma x P r), gamma fixed;
  //   i = 1, 2, 3: flow of T_i = 1/2 I_i Omega_i^2: I Omega and gamma rotate
  //      about body axis i by the angle -Omega_i h (Omega_i is constant).
  // Each conserves |gamma| and C0 = (I Omega).gamma up to round-off.
  void flow(int i, double h, State& x) const {
    if (i == 0) {
      const Vector3d g = x.tail<3>();
      x[0] += h * (g.y() * pr_.z() - g.z() * pr_.y()) * inv_inertia_.x();
      x[1] += h * (g.z() * pr_.x() - g.x() * pr_.z()) * inv_inertia_.y();
      x[2] += h * (g.x() * pr_.y() - g.y() * pr_.x()) * inv_inertia_.z();
      return;
    }
    const int k = i - 1;         // the rotation axis
    const int j1 = (k + 1) % 3;  // (j1, j2, k) is a cyclic order
    const int j2 = (k + 2) % 3;
    const double angle = -x[k] * h;
    const double c = std::cos(angle), s = std::sin(angle);
    // Angular momentum components about the two other axes.
    const double m1 = inertia_[j1] * x[j1], m2 = inertia_[j2] * x[j2];
    x[j1] = (c * m1 - s * m2) * inv_inertia_[j1];
    x[j2] = (s * m1 + c * m2) * inv_inertia_[j2];
    const double g1 = x[3 + j1], g2 = x[3 + j2];
    x[3 + j1] = c * g1 - s * g2;
    x[3 + j2] = s * g1 + c * g2;
  }

  // The symmetric composition K(h/2) R1(h/2) R2(h/2) R3(h) R2(h/2) R1(h/2) K(h/2)
  // (second order, conserves |gamma| and C0 to round-off).
  void strang_step(double h, State& x) const {
    flow(0, 0.5 * h, x);
    flow(1, 0.5 * h, x);
    flow(2, 0.5 * h, x);
    flow(3, h, x);
    flow(2, 0.5 * h, x);
    flow(1, 0.5 * h, x);
    flow(0, 0.5 * h, x);
  }

  const Vector3d& inertia() const { return inertia_; }

 private:
  Vector3d inertia_;
  Vector3d inv_inertia_;
  Vector3d pr_;
};

}  // namespace epviz::physics
