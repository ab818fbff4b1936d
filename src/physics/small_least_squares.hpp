#pragma once
// Levenberg–Marquardt for small systems of equations r(z) = 0 with an
// analytic Jacobian, square or not: the critical-state searches of the
// bifurcation diagram (physics/critical_values.hpp) solve 11 equations in 10
// unknowns, or 5 in 6, and need only to know whether the residual reaches
// round-off from a given start.
#include <Eigen/Core>
#include <functional>

namespace epviz::physics {

// Writes r(z) into `r` and its Jacobian dr/dz into `jacobian` (sized by the callee).
using ResidualFunction =
    std::function<void(const Eigen::VectorXd& z, Eigen::VectorXd& r, Eigen::MatrixXd& jacobian)>;

struct LeastSquaresResult {
  Eigen::VectorXd z;      // the best point reached
  double residual = 0.0;  // |r(z)| there
};

// Starts at z0 and stops when |r| <= tolerance, after `max_iterations`
// steps, or when no damping makes a step that lowers |r|.
LeastSquaresResult levenberg_marquardt(const ResidualFunction& f, Eigen::VectorXd z0,
                                       double tolerance, int max_iterations = 200);

}  // namespace epviz::physics
