#pragma once
// The linearised Riccati formulation (docs/math.md §3.4): eta = p / q
// with complex p, q (Cayley-Klein parameters),
//   p' = (beta/2) p + delta q,   q' = -alpha p - (beta/2) q,
//   alpha = (Omega2 + i Omega1)/2, beta = -i Omega3, delta = (Omega2 - i Omega1)/2,
// state (Omega, Re p, Im p, Re q, Im q), 7 dimensions. gamma follows by the Hopf
// map, without poles, and (p, q) also carry the body's full attitude.
//
// Attitude. The 2x2 matrix U = [[p, -conj q], [q, conj p]] solves U' = A U with
// A = -(i/2)(Omega1 sx - Omega2 sy + Omega3 sz) (Pauli matrices s). Writing the
// quaternion <-> SU(2) map as w + x i + y j + z k <-> w - i (x sx + y sy + z sz),
// the rotation Q = Ry(pi) Rot(U) (space -> body) satisfies Q' = -[Omega]x Q and
// Q e_z = gamma (the Hopf map). The attitude R = Q^T (body -> space) is then
//   R = (w, x, y, z) = (Re q, -Im p, Re p, Im q) / sqrt(|p|^2 + |q|^2),
// with R gamma = e_z and R' = R [Omega]x. Conversely p = y - i x, q = w + i z.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

#include "physics/body.hpp"
#include "physics/direct.hpp"

namespace epviz::physics {

class SpinorSystem {
 public:
  static constexpr int dim = 7;
  using State = Eigen::Matrix<double, 7, 1>;
  static constexpr const char* name = "spinor";

  explicit SpinorSystem(const Body& body)
      : inertia_(body.inertia),
        inv_inertia_(body.inertia.cwiseInverse()),
        pr_(body.weight * body.com) {}

  // x = (Omega, Re p, Im p, Re q, Im q).
  [[gnu::always_inline]] void rhs(double /*t*/, const State& x, State& dxdt) const {
    const Vector3d w = x.head<3>();
    const double pr = x[3], pi = x[4], qr = x[5], qi = x[6];
    dxdt.head<3>() = euler_omega_dot(inertia_, inv_inertia_, pr_, w, gamma(x));
    dxdt[3] = 0.5 * (w.z() * pi + w.y() * qr + w.x() * qi);
    dxdt[4] = 0.5 * (-w.z() * pr + w.y() * qi - w.x() * qr);
    dxdt[5] = 0.5 * (-w.y() * pr + w.x() * pi - w.z() * qi);
    dxdt[6] = 0.5 * (-w.x() * pr - w.y() * pi + w.z() * qr);
  }

  // (p, q) from the attitude that takes gamma0 to e_z along the shortest arc.
  static State pack(const InitialState& s) {
    return pack(s.omega, Eigen::Quaterniond::FromTwoVectors(s.gamma, Vector3d::UnitZ()));
  }

  // (p, q) of a given attitude (body -> space), normalised to |p|^2 + |q|^2 = 1.
  static State pack(const Vector3d& omega, const Eigen::Quaterniond& attitude) {
    const Eigen::Quaterniond r = attitude.normalized();
    State x;
    x.head<3>() = omega;
    x[3] = r.y();   // Re p
    x[4] = -r.x();  // Im p
    x[5] = r.w();   // Re q
    x[6] = r.z();   // Im q
    return x;
  }

  Vector3d omega(const State& x) const { return x.head<3>(); }

  // The Hopf map (sigma = 1).
  [[gnu::always_inline]] static Vector3d gamma(const State& x) {
    const double pr = x[3], pi = x[4], qr = x[5], qi = x[6];
    const double pp = pr * pr + pi * pi, qq = qr * qr + qi * qi;
    const double inv = 1.0 / (pp + qq);
    // p conj(q) = (pr qr + pi qi) + i (pi qr - pr qi)
    return Vector3d(-2.0 * (pr * qr + pi * qi) * inv, -2.0 * (pi * qr - pr * qi) * inv,
                    (qq - pp) * inv);
  }

  // Rotation body -> space: attitude * gamma == e_z, d/dt attitude = attitude [Omega]x.
  static Eigen::Quaterniond attitude(const State& x) {
    return Eigen::Quaterniond(x[5], -x[4], x[3], x[6]).normalized();
  }

  // |p|^2 + |q|^2 (conserved by the exact flow).
  static double norm2(const State& x) { return x.tail<4>().squaredNorm(); }

 private:
  Vector3d inertia_;
  Vector3d inv_inertia_;
  Vector3d pr_;
};

}  // namespace epviz::physics
