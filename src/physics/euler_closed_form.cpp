#include "physics/euler_closed_form.hpp"

#include <algorithm>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace epviz::physics {

namespace {

// F(phi, k) for phi in [-pi, pi] (odd, and F(pi - x) = 2 K - F(x)).
double incomplete_f(double phi, double k) {
  const double half_pi = 0.5 * std::numbers::pi;
  const double s = phi < 0.0 ? -1.0 : 1.0;
  const double a = std::abs(phi);
  if (a <= half_pi) return s * boost::math::ellint_1(k, a);
  return s * (2.0 * boost::math::ellint_1(k) - boost::math::ellint_1(k, std::numbers::pi - a));
}

// +1 for an even permutation (i, j, l) of (0, 1, 2), -1 for an odd one.
int parity(int i, int j, int l) { return ((j - i + 3) % 3 == 1 && (l - j + 3) % 3 == 1) ? 1 : -1; }

}  // namespace

EulerClosedForm::EulerClosedForm(const Eigen::Vector3d& I, const Eigen::Vector3d& w0) {
  if (!I.allFinite() || !(I.minCoeff() > 0.0) || !w0.allFinite())
    throw std::invalid_argument(
        "EulerClosedForm: moments must be positive and finite, omega finite");
  const double scale = I.cwiseAbs().maxCoeff();
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (std::abs(I[i] - I[j]) <= 1e-12 * scale)
        throw std::invalid_argument("EulerClosedForm: the moments must be distinct");
  if (w0.squaredNorm() == 0.0)
    throw std::invalid_argument("EulerClosedForm: omega0 = 0 (the body is at rest)");

  int order[3] = {0, 1, 2};  // ascending moments
  std::sort(order, order + 3, [&](int x, int y) { return I[x] < I[y]; });
  const double m2 = I.cwiseProduct(w0).squaredNorm();  // M^2
  const double e2 = I.cwiseProduct(w0).dot(w0);        // 2E
  const double mid = I[order[1]];
  const double gap = m2 - e2 * mid;
  if (std::abs(gap) <= 1e-12 * m2)
    throw std::invalid_argument(
        "EulerClosedForm: the motion lies on the separatrix (M^2 = 2 E I_mid)");
  // Roles 1, 2, 3 of docs/math.md §2.4: 3 = the axis Omega keeps its sign on.
  if (gap > 0.0) {
    ax_[0] = order[0];
    ax_[1] = order[1];
    ax_[2] = order[2];
  } else {
    ax_[0] = order[2];
    ax_[1] = order[1];
    ax_[2] = order[0];
  }
  const double I1 = I[ax_[0]], I2 = I[ax_[1]], I3 = I[ax_[2]];
  // Every ratio below is of two quantities of the same sign in either regime;
  // clamp round-off when the motion is (nearly) a pure rotation about axis 3.
  const double u = std::max(0.0, (e2 * I3 - m2) / (I3 - I1));  // (2E I3 - M^2)/(I3 - I1)
  const double v = std::max(0.0, (m2 - e2 * I1) / (I3 - I1));  // (M^2 - 2E I1)/(I3 - I1)
  const double A1 = std::sqrt(u / I1);
  const double A2 = std::sqrt(u * (I3 - I1) / (I2 * (I3 - I2)));
  const double A3 = std::sqrt(v / I3);
  lambda_ = std::sqrt(v * (I3 - I2) * (I3 - I1) / (I1 * I2 * I3));
  const double m = std::clamp((I2 - I1) * u / ((I3 - I2) * v), 0.0, 1.0);
  k_ = std::sqrt(m);
  // In these labels the Euler equations read I1 W1' = eps (I2 - I3) W2 W3 (cyclic),
  // eps the parity of the relabelling; the ansatz W1 = A1 cn, W2 = nu A2 sn,
  // W3 = s3 A3 dn solves them with nu = s3 eps sign(I3 - I2).
  const double s3 = w0[ax_[2]] < 0.0 ? -1.0 : 1.0;
  const double eps = parity(ax_[0], ax_[1], ax_[2]);
  const double nu = s3 * eps * (I3 > I2 ? 1.0 : -1.0);
  amp_[0] = A1;
  amp_[1] = nu * A2;
  amp_[2] = s3 * A3;
  // tau0: cn(tau0) = W1(0)/A1, sn(tau0) = W2(0)/(nu A2), i.e. am(tau0) = phi0.
  const double phi0 = std::atan2(w0[ax_[1]] * nu * A1, w0[ax_[0]] * A2);
  tau0_ = incomplete_f(phi0, k_);
}

Eigen::Vector3d EulerClosedForm::omega(double t) const {
  double cn = 0.0, dn = 0.0;
  const double sn = boost::math::jacobi_elliptic(k_, lambda_ * t + tau0_, &cn, &dn);
  Eigen::Vector3d w;
  w[ax_[0]] = amp_[0] * cn;
  w[ax_[1]] = amp_[1] * sn;
  w[ax_[2]] = amp_[2] * dn;
  return w;
}

double EulerClosedForm::period() const { return 4.0 * boost::math::ellint_1(k_) / lambda_; }

}  // namespace epviz::physics
