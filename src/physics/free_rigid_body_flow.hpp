#pragma once
// The exact flow of the free (torque-free) rigid body on the direct state
// (Omega, gamma), and the splitting system "kick + exact free flow" built on it.
//
// Free flow over time h (Celledoni, Fasso, Safstrom and Zanna, "The exact
// computation of the free rigid body motion and its use in splitting methods",
// SIAM J. Sci. Comput. 30(4), 2008):
//   * M = I Omega follows the Euler equations in closed form (Jacobi elliptic
//     functions, docs/math.md §2.4-2.5, any axis ordering, either side of the
//     separatrix);
//   * the attitude is Q(t) = A(M(0))^T R3(psi(t)) A(M(t)), where A(M) is a
//     rotation taking the body vector M/|M| to e3 and R3 a rotation about e3;
//     psi(t) = 2T t/|M| + (a term with an incomplete elliptic integral of the
//     third kind, see the .cpp);
//   * gamma (a space-fixed vector seen from the body) is gamma(h) = Q(h)^T gamma(0).
// Conserves |gamma|, |M|, the kinetic energy and C0 = M.gamma up to round-off.
#include <Eigen/Core>

#include "physics/body.hpp"
#include "physics/direct.hpp"

namespace epviz::physics {

class FreeRigidBodyFlow {
 public:
  // Which closed form advance() used (the most recent call; for tests).
  enum class Path { rest, steady, symmetric, elliptic, separatrix };

  // inertia: principal moments, positive and finite (throws std::invalid_argument otherwise).
  explicit FreeRigidBodyFlow(const Vector3d& inertia);

  // Advances (omega, gamma) by time h (any sign, any size) along the torque-free motion.
  //  - Omega = 0: nothing moves.
  //  - Omega along a principal axis (two components exactly 0): steady rotation.
  //  - two equal moments (relative 1e-12): closed-form regular precession.
  //  - |M^2 - 2E I_mid| <= separatrix_tol M^2 (includes rotation close to the middle
  //    axis): tiny-step RK4 of the free body (|Omega| dt <= 4e-4), error ~1e-12 per
  //    unit of |Omega| t.
  //  - otherwise: Jacobi elliptic functions and the elliptic integral of the third kind.
  Path advance(double h, Vector3d& omega, Vector3d& gamma) const;

  static constexpr double separatrix_tol = 1e-10;
  const Vector3d& inertia() const { return inertia_; }

 private:
  Path symmetric(double h, int axis, Vector3d& omega, Vector3d& gamma) const;
  Path elliptic(double h, Vector3d& omega, Vector3d& gamma) const;
  Path separatrix(double h, Vector3d& omega, Vector3d& gamma) const;

  Vector3d inertia_;
  int sym_axis_ = -1;  // the axis of symmetry when two (or three) moments are equal
};

// The direct formulation split into two exactly solvable sub-flows:
//   flow(0, h): gravity kick, Omega += h I^-1 (gamma x P r), gamma fixed;
//   flow(1, h): the exact free rigid body flow (FreeRigidBodyFlow).
// Strang K(h/2) F(h) K(h/2) over these is "exact-split2"; a 4th-order
// composition of it (numerics/composition.hpp) is "exact-split4".
class ExactSplitSystem {
 public:
  static constexpr int dim = 6;
  using State = DirectSystem::State;
  static constexpr const char* name = "direct";
  static constexpr int n_flows = 2;

  explicit ExactSplitSystem(const Body& body) : direct_(body), free_(body.inertia) {}

  void rhs(double t, const State& x, State& dxdt) const { direct_.rhs(t, x, dxdt); }
  static State pack(const InitialState& s) { return DirectSystem::pack(s); }
  Vector3d omega(const State& x) const { return x.head<3>(); }
  Vector3d gamma(const State& x) const { return x.tail<3>(); }

  void flow(int i, double h, State& x) const {
    if (i == 0) {
      direct_.flow(0, h, x);
      return;
    }
    Vector3d w = x.head<3>(), g = x.tail<3>();
    free_.advance(h, w, g);
    x << w, g;
  }

  const FreeRigidBodyFlow& free_flow() const { return free_; }

 private:
  DirectSystem direct_;
  FreeRigidBodyFlow free_;
};

}  // namespace epviz::physics
