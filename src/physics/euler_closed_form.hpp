#pragma once
// Torque-free motion (Euler case) in closed form by Jacobi elliptic functions,
// docs/math.md §2.4: a test oracle for the integrators.
#include <Eigen/Core>

namespace epviz::physics {

class EulerClosedForm {
 public:
  // Any ordering of three distinct positive moments, either regime
  // (M^2 > 2 E I_mid: rotation about the axis of the largest moment;
  //  M^2 < 2 E I_mid: about the smallest). Throws std::invalid_argument for
  // non-positive or equal moments, Omega0 = 0 or non-finite input, and for the
  // separatrix |M^2 - 2 E I_mid| <= 1e-12 M^2 (including Omega0 along the middle axis).
  EulerClosedForm(const Eigen::Vector3d& inertia, const Eigen::Vector3d& omega0);

  // Omega(t) with Omega(0) = omega0.
  Eigen::Vector3d omega(double t) const;

  double modulus() const { return k_; }         // k (m = k^2)
  double frequency() const { return lambda_; }  // lambda: tau = lambda t + tau0
  double period() const;                        // period of Omega(t): 4 K(k) / lambda
  int dominant_axis() const { return ax_[2]; }  // 0-based axis Omega never crosses zero on

 private:
  int ax_[3];      // body axes playing the roles 1, 2, 3 of docs/math.md §2.4
  double amp_[3];  // A1, nu A2, s3 A3 (signs included)
  double k_ = 0.0;
  double lambda_ = 0.0;
  double tau0_ = 0.0;
};

}  // namespace epviz::physics
