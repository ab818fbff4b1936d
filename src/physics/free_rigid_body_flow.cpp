#include "physics/free_rigid_body_flow.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_3.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace epviz::physics {

namespace {

constexpr double kPi = std::numbers::pi;

// Double precision throughout: Boost's default promotes double to long double
// internally, which costs ~5x here for accuracy the tests show is not needed.
using Pol = boost::math::policies::policy<boost::math::policies::promote_double<false>>;

// Rotates v about the unit vector `axis` by `angle` (right-handed, Rodrigues).
Vector3d rotate(const Vector3d& axis, double angle, const Vector3d& v) {
  const double c = std::cos(angle), s = std::sin(angle);
  return c * v + s * axis.cross(v) + (1.0 - c) * axis.dot(v) * axis;
}

// +1 for an even permutation (i, j, l) of (0, 1, 2), -1 for an odd one.
double parity(int i, int j, int l) {
  return ((j - i + 3) % 3 == 1 && (l - j + 3) % 3 == 1) ? 1.0 : -1.0;
}

// F(phi, k) and Pi(n; phi, k) = int_0^phi dt / ((1 - n sin^2 t) sqrt(1 - k^2 sin^2 t))
// for any real phi, by F(phi + p pi) = F(phi) + 2 p K and Pi(phi + p pi) = Pi(phi)
// + 2 p Pi(n) (both odd in phi). `kc`, `pic`: the complete integrals.
double incomplete_f(double phi, double k, double kc) {
  const double p = std::round(phi / kPi);
  const double x = phi - p * kPi;  // in [-pi/2, pi/2]
  const double f = boost::math::ellint_1(k, std::abs(x), Pol());
  return 2.0 * p * kc + (x < 0.0 ? -f : f);
}
double incomplete_pi(double n, double phi, double k, double pic) {
  const double p = std::round(phi / kPi);
  const double x = phi - p * kPi;
  const double v = boost::math::ellint_3(k, n, std::abs(x), Pol());
  return 2.0 * p * pic + (x < 0.0 ? -v : v);
}

}  // namespace

FreeRigidBodyFlow::FreeRigidBodyFlow(const Vector3d& inertia) : inertia_(inertia) {
  if (!inertia.allFinite() || !(inertia.minCoeff() > 0.0))
    throw std::invalid_argument("FreeRigidBodyFlow: the moments must be positive and finite");
  const double scale = inertia.maxCoeff();
  auto eq = [&](int i, int j) { return std::abs(inertia[i] - inertia[j]) <= 1e-12 * scale; };
  if (eq(0, 1))
    sym_axis_ = 2;
  else if (eq(1, 2))
    sym_axis_ = 0;
  else if (eq(0, 2))
    sym_axis_ = 1;
}

FreeRigidBodyFlow::Path FreeRigidBodyFlow::advance(double h, Vector3d& omega,
                                                   Vector3d& gamma) const {
  const int zeros = int(omega[0] == 0.0) + int(omega[1] == 0.0) + int(omega[2] == 0.0);
  if (zeros == 3 || h == 0.0) return Path::rest;
  if (zeros == 2) {
    // Steady rotation about a principal axis: gamma' = gamma x Omega.
    const double w = omega.norm();
    gamma = rotate(omega / w, -w * h, gamma);
    return Path::steady;
  }
  if (sym_axis_ >= 0) return symmetric(h, sym_axis_, omega, gamma);
  return elliptic(h, omega, gamma);
}

// Two equal moments I_t (transverse), I_s about the axis s. With beta =
// M_s (1/I_s - 1/I_t), Omega = M/I_t + beta e_s, and the attitude is
// Q(t) = exp(t hat(M0)/I_t) exp(t beta hat(e_s)) (Q' = Q hat(Omega), Q M(t) = M0), so
//   M(t) = Rot(e_s, -beta t) M0,  gamma(t) = Rot(e_s, -beta t) Rot(M0/|M0|, -|M0| t/I_t) gamma0.
// Also exact when all three moments are equal (beta = 0).
FreeRigidBodyFlow::Path FreeRigidBodyFlow::symmetric(double h, int s, Vector3d& omega,
                                                     Vector3d& gamma) const {
  const double it = inertia_[(s + 1) % 3];
  const Vector3d m0 = inertia_.cwiseProduct(omega);
  const double mn = m0.norm();
  const double beta = m0[s] * (1.0 / inertia_[s] - 1.0 / it);
  const Vector3d es = Vector3d::Unit(s);
  gamma = rotate(es, -beta * h, rotate(m0 / mn, -mn * h / it, gamma));
  omega = rotate(es, -beta * h, m0).cwiseQuotient(inertia_);
  return Path::symmetric;
}

// Distinct moments. Labels 1, 2, 3 (docs/math.md §2.4): 3 is the axis Omega keeps
// its sign on (largest moment when M^2 > 2E I_mid, smallest otherwise):
//   M1 = c1 cn(tau), M2 = c2 sn(tau), M3 = c3 dn(tau), tau = tau0 + lambda t.
// Attitude (Celledoni et al. 2008, sec. 3): Q(t) = A(M0)^T R3(psi(t)) A(M(t)), with
// A(M) the rotation whose rows are (a, b, m), m = M/|M|, a = e3 x m/|e3 x m|,
// b = m x a. Then Q^T Q' = hat(Omega) gives psi' = 2T/|M| - a.b', and with
// a.b' computed from the rows,
//   psi' = 2T/|M| + eps m3 (m1 m2' - m2 m1') / (m1^2 + m2^2)
//        = 2T/|M| + eps (c2 c3 / (c1 |M|)) lambda dn^2 / (1 - n sn^2),
//   n = 1 - c2^2/c1^2 = I3 (I1 - I2) / (I1 (I3 - I2))   (always < 0),
// eps the parity of the labelling (e1, e2, e3 as body axes). With
// dn^2/(1 - n sn^2) = r + (1 - r)/(1 - n sn^2), r = k^2/n = -I1 u/(I3 v), and
// int dtau/(1 - n sn^2) = Pi(n; am tau, k) (incomplete elliptic integral of the
// third kind, Boost's ellint_3(k, n, phi)):
//   psi(h) = 2T h/|M| + eps c2 c3/(c1 |M|) [r lambda h + (1 - r)(Pi(n; am tau1) - Pi(n; am tau0))].
// e3 x m never vanishes (M1 and M2 are never zero together), so A is smooth.
FreeRigidBodyFlow::Path FreeRigidBodyFlow::elliptic(double h, Vector3d& omega,
                                                    Vector3d& gamma) const {
  const Vector3d& I = inertia_;
  const Vector3d w = omega;
  int o[3] = {0, 1, 2};  // ascending moments
  std::sort(o, o + 3, [&](int x, int y) { return I[x] < I[y]; });
  const double m2 = I.cwiseProduct(w).squaredNorm();  // M^2
  // M^2 - 2E I_mid, summed without cancellation.
  const double gap = I[o[0]] * w[o[0]] * w[o[0]] * (I[o[0]] - I[o[1]]) +
                     I[o[2]] * w[o[2]] * w[o[2]] * (I[o[2]] - I[o[1]]);
  if (std::abs(gap) <= separatrix_tol * m2) return separatrix(h, omega, gamma);
  const int i1 = gap > 0.0 ? o[0] : o[2], i2 = o[1], i3 = gap > 0.0 ? o[2] : o[0];
  const double I1 = I[i1], I2 = I[i2], I3 = I[i3];
  const double w1 = w[i1], w2 = w[i2], w3 = w[i3];
  // u = (2E I3 - M^2)/(I3 - I1), v = (M^2 - 2E I1)/(I3 - I1), both >= 0, without cancellation.
  const double u = I1 * w1 * w1 + I2 * w2 * w2 * (I3 - I2) / (I3 - I1);
  const double v = I2 * w2 * w2 * (I2 - I1) / (I3 - I1) + I3 * w3 * w3;
  const double A1 = std::sqrt(u / I1);
  const double A2 = std::sqrt(u * (I3 - I1) / (I2 * (I3 - I2)));
  const double A3 = std::sqrt(v / I3);
  const double lambda = std::sqrt(v * (I3 - I2) * (I3 - I1) / (I1 * I2 * I3));
  const double k = std::sqrt(std::clamp((I2 - I1) * u / ((I3 - I2) * v), 0.0, 1.0));
  const double s3 = w3 < 0.0 ? -1.0 : 1.0;
  const double eps = parity(i1, i2, i3);
  const double nu = s3 * eps * (I3 > I2 ? 1.0 : -1.0);
  const double kc = boost::math::ellint_1(k, Pol());
  // am(tau0) = phi0: cn(tau0) = w1/A1, sn(tau0) = w2/(nu A2).
  const double phi0 = std::atan2(w2 * nu * A1, w1 * A2);
  const double tau0 = incomplete_f(phi0, k, kc);
  const double tau1 = tau0 + lambda * h;
  const double j = std::round(tau1 / (2.0 * kc));
  const double taur = tau1 - 2.0 * j * kc;  // in [-K, K]: am(taur) in [-pi/2, pi/2]
  double cn = 0.0, dn = 0.0;
  const double sn = boost::math::jacobi_elliptic(k, taur, &cn, &dn, Pol());
  const double flip = std::fmod(j, 2.0) == 0.0 ? 1.0 : -1.0;  // sn, cn change sign with tau + 2K
  Vector3d wn;
  wn[i1] = flip * A1 * cn;
  wn[i2] = flip * nu * A2 * sn;
  wn[i3] = s3 * A3 * dn;
  const double phi1 = j * kPi + std::atan2(sn, cn);  // am(tau1), continuous

  const double mnorm = std::sqrt(m2);
  const double n = I3 * (I1 - I2) / (I1 * (I3 - I2));
  const double r = -I1 * u / (I3 * v);
  const double pic = boost::math::ellint_3(k, n, Pol());
  const double dpi = incomplete_pi(n, phi1, k, pic) - incomplete_pi(n, phi0, k, pic);
  const double c2_over_c1 = nu * (I2 / I1) * std::sqrt(I1 * (I3 - I1) / (I2 * (I3 - I2)));
  const double c3 = s3 * I3 * A3;
  const double two_t = I.cwiseProduct(w).dot(w);
  const double psi =
      two_t * h / mnorm + eps * c2_over_c1 * c3 / mnorm * (r * lambda * h + (1.0 - r) * dpi);

  const Vector3d e3 = Vector3d::Unit(i3);
  const Vector3d ma = I.cwiseProduct(w).normalized();
  const Vector3d aa = e3.cross(ma).normalized();
  const Vector3d ba = ma.cross(aa);
  const Vector3d mb = I.cwiseProduct(wn).normalized();
  const Vector3d ab = e3.cross(mb).normalized();
  const Vector3d bb = mb.cross(ab);
  const double x = aa.dot(gamma), y = ba.dot(gamma), z = ma.dot(gamma);
  const double c = std::cos(psi), s = std::sin(psi);
  gamma = (c * x + s * y) * ab + (c * y - s * x) * bb + z * mb;
  omega = wn;
  return Path::elliptic;
}

// On (or within separatrix_tol of) the separatrix the elliptic modulus is 1 and
// the period infinite: integrate the free body (Omega' = I^-1 (I Omega x Omega),
// gamma' = gamma x Omega) by classical RK4 with |Omega| dt <= 4e-4.
FreeRigidBodyFlow::Path FreeRigidBodyFlow::separatrix(double h, Vector3d& omega,
                                                      Vector3d& gamma) const {
  using V6 = Eigen::Matrix<double, 6, 1>;
  const Vector3d I = inertia_;
  auto f = [&](const V6& x) {
    const Vector3d w = x.head<3>(), g = x.tail<3>();
    V6 d;
    d << I.cwiseProduct(w).cross(w).cwiseQuotient(I), g.cross(w);
    return d;
  };
  // |Omega| is bounded by |M| / I_min along the motion.
  const double wmax = I.cwiseProduct(omega).norm() / I.minCoeff();
  const long steps = std::max(1L, long(std::ceil(std::abs(h) * wmax / 4e-4)));
  const double dt = h / double(steps);
  V6 x;
  x << omega, gamma;
  for (long i = 0; i < steps; ++i) {
    const V6 k1 = f(x);
    const V6 k2 = f(x + 0.5 * dt * k1);
    const V6 k3 = f(x + 0.5 * dt * k2);
    const V6 k4 = f(x + dt * k3);
    x += (dt / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  omega = x.head<3>();
  gamma = x.tail<3>();
  return Path::separatrix;
}

}  // namespace epviz::physics
