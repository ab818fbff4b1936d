#include "physics/small_least_squares.hpp"

#include <Eigen/Cholesky>
#include <cmath>

namespace epviz::physics {

LeastSquaresResult levenberg_marquardt(const ResidualFunction& f, Eigen::VectorXd z0,
                                       double tolerance, int max_iterations) {
  Eigen::VectorXd r, r_new;
  Eigen::MatrixXd j, j_new;
  f(z0, r, j);
  LeastSquaresResult best{std::move(z0), r.norm()};
  // Damping relative to the Jacobian's scale; lowered after a good step, so
  // that near a solution the steps become Gauss–Newton's (quadratic
  // convergence where the solution is regular, least-norm where it is not).
  double lambda = 1e-3;
  for (int it = 0; it < max_iterations && best.residual > tolerance; ++it) {
    if (!std::isfinite(best.residual)) break;
    const Eigen::MatrixXd normal = j.transpose() * j;
    const Eigen::VectorXd gradient = j.transpose() * r;
    const double scale = std::max(normal.diagonal().maxCoeff(), 1e-300);
    bool improved = false;
    for (int tries = 0; tries < 12 && !improved; ++tries) {
      Eigen::MatrixXd damped = normal;
      damped.diagonal().array() += lambda * scale;
      const Eigen::VectorXd step = damped.ldlt().solve(-gradient);
      const Eigen::VectorXd z = best.z + step;
      f(z, r_new, j_new);
      const double norm = r_new.norm();
      if (std::isfinite(norm) && norm < best.residual) {
        best = {z, norm};
        r.swap(r_new);
        j.swap(j_new);
        lambda = std::max(lambda * 0.2, 1e-15);
        improved = true;
      } else {
        lambda *= 8.0;
      }
    }
    if (!improved) break;
  }
  return best;
}

}  // namespace epviz::physics
