#include "physics/kovalevskaya_critical_states.hpp"

#include <Eigen/SVD>
#include <cmath>

#include "physics/level_set.hpp"
#include "physics/small_least_squares.hpp"

namespace epviz::physics::kovalevskaya {
namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

const Eigen::Vector3d kInertia(2.0, 2.0, 1.0);

// Values, gradients and Hessians in x = (Ω1, Ω2, Ω3, γ1, γ2, γ3) of the
// normalised body's integrals, in the order C0, C1, K, |γ|².
struct Integrals {
  Eigen::Vector4d value;
  Eigen::Matrix<double, 6, 4> gradient;
  Matrix6d hessian[4];
  // K's two squares X = Ω1² − Ω2² − γ1, Y = 2 Ω1 Ω2 − γ2 and their gradients.
  double x = 0.0, y = 0.0;
  Vector6d grad_x, grad_y;
};

Integrals integrals(const Vector6d& s) {
  const Eigen::Vector3d w = s.head<3>(), g = s.tail<3>();
  const Eigen::Vector3d iw = kInertia.cwiseProduct(w), ig = kInertia.cwiseProduct(g);
  Integrals f;
  f.x = w(0) * w(0) - w(1) * w(1) - g(0);
  f.y = 2.0 * w(0) * w(1) - g(1);
  f.grad_x << 2.0 * w(0), -2.0 * w(1), 0.0, -1.0, 0.0, 0.0;
  f.grad_y << 2.0 * w(1), 2.0 * w(0), 0.0, 0.0, -1.0, 0.0;
  f.value << iw.dot(g), 0.5 * iw.dot(w) + g(0), f.x * f.x + f.y * f.y, g.squaredNorm();
  f.gradient.col(0) << ig, iw;
  f.gradient.col(1) << iw, 1.0, 0.0, 0.0;
  f.gradient.col(2) = 2.0 * (f.x * f.grad_x + f.y * f.grad_y);
  f.gradient.col(3) << 0.0, 0.0, 0.0, 2.0 * g;
  for (auto& h : f.hessian) h.setZero();
  f.hessian[0].topRightCorner<3, 3>() = kInertia.asDiagonal();
  f.hessian[0].bottomLeftCorner<3, 3>() = kInertia.asDiagonal();
  f.hessian[1].topLeftCorner<3, 3>() = kInertia.asDiagonal();
  Matrix6d hx = Matrix6d::Zero(), hy = Matrix6d::Zero();
  hx(0, 0) = 2.0;
  hx(1, 1) = -2.0;
  hy(0, 1) = hy(1, 0) = 2.0;
  f.hessian[2] = 2.0 * (f.grad_x * f.grad_x.transpose() + f.grad_y * f.grad_y.transpose() +
                        f.x * hx + f.y * hy);
  f.hessian[3].bottomRightCorner<3, 3>() = 2.0 * Eigen::Matrix3d::Identity();
  return f;
}

// C0 = ℓ, C1 = h, X = 0, Y = 0, |γ|² = 1 in the 6 unknowns x.
ResidualFunction k_zero_equations(double area, double energy) {
  return [=](const Eigen::VectorXd& z, Eigen::VectorXd& r, Eigen::MatrixXd& j) {
    const Integrals f = integrals(z.head<6>());
    r.resize(5);
    j.resize(5, 6);
    r << f.value(0) - area, f.value(1) - energy, f.x, f.y, f.value(3) - 1.0;
    j.row(0) = f.gradient.col(0).transpose();
    j.row(1) = f.gradient.col(1).transpose();
    j.row(2) = f.grad_x.transpose();
    j.row(3) = f.grad_y.transpose();
    j.row(4) = f.gradient.col(3).transpose();
  };
}

// Σ μ_i ∇F_i = 0, F = (ℓ, h, k, 1), |μ|² = 1 in the 10 unknowns (x, μ).
ResidualFunction multiplier_equations(double area, double energy, double k) {
  const Eigen::Vector4d target(area, energy, k, 1.0);
  return [=](const Eigen::VectorXd& z, Eigen::VectorXd& r, Eigen::MatrixXd& j) {
    const Integrals f = integrals(z.head<6>());
    const Eigen::Vector4d mu = z.tail<4>();
    r.resize(11);
    j.setZero(11, 10);
    r.head<6>() = f.gradient * mu;
    r.segment<4>(6) = f.value - target;
    r(10) = mu.squaredNorm() - 1.0;
    for (int i = 0; i < 4; ++i) j.topLeftCorner<6, 6>() += mu(i) * f.hessian[i];
    j.topRightCorner<6, 4>() = f.gradient;
    j.block<4, 6>(6, 0) = f.gradient.transpose();
    j.block<1, 4>(10, 6) = 2.0 * mu.transpose();
  };
}

double uniform(std::mt19937_64& random, double lo, double hi) {
  // From the generator's bits, not std::uniform_real_distribution, whose
  // output the standard leaves to the library: the same seed, the same figure.
  return lo + (hi - lo) * double(random() >> 11) * 0x1.0p-53;
}

Eigen::Vector3d random_unit(std::mt19937_64& random) {
  for (;;) {
    const Eigen::Vector3d v(uniform(random, -1, 1), uniform(random, -1, 1), uniform(random, -1, 1));
    if (v.norm() > 0.1 && v.norm() <= 1.0) return v.normalized();
  }
}

}  // namespace

std::optional<Eigen::VectorXd> solve_critical_state(CriticalKind kind, double area, double energy,
                                                    double k,
                                                    const std::vector<Eigen::VectorXd>& starts) {
  const ResidualFunction f = kind == CriticalKind::k_zero ? k_zero_equations(area, energy)
                                                          : multiplier_equations(area, energy, k);
  // The equations' terms grow with the values: the residual is judged at their scale.
  const double tolerance =
      kAttainedResidual * std::max({1.0, std::abs(energy), std::abs(k), area * area});
  for (const auto& z0 : starts) {
    const auto result = levenberg_marquardt(f, z0, 0.01 * tolerance);
    if (result.residual <= tolerance) return result.z;
  }
  return std::nullopt;
}

std::vector<Eigen::VectorXd> random_starts(CriticalKind kind, double area, double energy, int count,
                                           std::mt19937_64& random) {
  const Body body{kInertia, Eigen::Vector3d(1.0, 0.0, 0.0), 1.0};
  std::vector<Vector3d> gammas;
  for (int i = 0; i < 4 * count; ++i) gammas.push_back(random_unit(random));
  const LevelStates level = level_states(body, Level{energy, area}, gammas);
  std::vector<Eigen::VectorXd> starts;
  for (const auto& s : level.states) {
    if (int(starts.size()) == count) break;
    Vector6d x;
    x << s.omega, s.gamma;
    if (kind == CriticalKind::k_zero) {
      starts.emplace_back(x);
      continue;
    }
    // The multipliers of the least dependent combination: the right singular
    // vector of the gradients' smallest singular value.
    const Eigen::JacobiSVD<Eigen::Matrix<double, 6, 4>> svd(integrals(x).gradient,
                                                            Eigen::ComputeFullV);
    Eigen::VectorXd z(10);
    z << x, svd.matrixV().col(3);
    starts.push_back(std::move(z));
  }
  return starts;
}

}  // namespace epviz::physics::kovalevskaya
