#include "physics/andoyer.hpp"

#include <Eigen/Geometry>  // cross()
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace epviz::physics {
namespace {

// atan2 in (−π, π]: atan2(−0, negative) is −π, the same direction as π.
double angle_of(double sine, double cosine) {
  const double a = std::atan2(sine, cosine);
  return a == -std::numbers::pi ? std::numbers::pi : a;
}

}  // namespace

std::string_view name(AndoyerSingularity s) {
  switch (s) {
    case AndoyerSingularity::none: return "none";
    case AndoyerSingularity::no_momentum: return "G = 0";
    case AndoyerSingularity::momentum_on_axis3: return "L = ±G";
    case AndoyerSingularity::momentum_vertical: return "H = ±G";
  }
  return "";
}

AndoyerVariables andoyer_variables(const Body& body, const Vector3d& omega, const Vector3d& gamma) {
  const Vector3d m = body.inertia.cwiseProduct(omega);
  AndoyerVariables a;
  a.L = m.z();
  a.G = m.norm();
  a.H = m.dot(gamma);
  if (!(a.G > 0.0)) {
    a.singularity = AndoyerSingularity::no_momentum;
    return a;
  }
  // The nodes (docs/math.md §1.6): n2 = M × e3, where the body's equator
  // meets the invariant plane; n1 = γ × M, where the invariant plane meets
  // the horizontal one.
  const Vector3d n2(m.y(), -m.x(), 0.0);
  const Vector3d n1 = gamma.cross(m);
  if (n2.norm() <= kAndoyerSingularSine * a.G) {
    a.singularity = AndoyerSingularity::momentum_on_axis3;
    return a;
  }
  // l: from n2 to e1, counterclockwise about e3.
  a.l = angle_of(m.x(), m.y());
  if (n1.norm() <= kAndoyerSingularSine * a.G * gamma.norm()) {
    a.singularity = AndoyerSingularity::momentum_vertical;
    return a;
  }
  // g: from n1 to n2, counterclockwise about M.
  a.g = angle_of(n1.cross(n2).dot(m) / a.G, n1.dot(n2));
  return a;
}

InitialState andoyer_state(const Body& body, double l, double L, double g, double G, double H) {
  for (double x : {l, L, g, G, H})
    if (!std::isfinite(x)) throw std::invalid_argument("andoyer_state: a number is not finite");
  if (!(G > 0.0 && std::abs(L) < G && std::abs(H) < G))
    throw std::invalid_argument("andoyer_state: needs G > 0, |L| < G and |H| < G");
  const double cos_i = L / G, sin_i = std::sqrt((G - L) * (G + L)) / G;
  const double cos_j = H / G, sin_j = std::sqrt((G - H) * (G + H)) / G;
  // M's direction, the node n2 and u = M̂ × n2 completing the invariant plane.
  const Vector3d m_hat(sin_i * std::sin(l), sin_i * std::cos(l), cos_i);
  const Vector3d n2(std::cos(l), -std::sin(l), 0.0);
  const Vector3d u = m_hat.cross(n2);
  // γ at the angle J from M, its horizontal node n1 at −g from n2: γ lies
  // along M̂ × n1 = cos g u + sin g n2 beside M̂.
  InitialState s;
  s.gamma = cos_j * m_hat + sin_j * (std::cos(g) * u + std::sin(g) * n2);
  s.omega = (G * m_hat).cwiseQuotient(body.inertia);
  return s;
}

AngleSides andoyer_angle_sides(AndoyerAngle a, const Body& body, const Vector3d& omega,
                               const Vector3d& gamma) {
  const Vector3d m = body.inertia.cwiseProduct(omega);
  if (a == AndoyerAngle::l) return {m.x(), m.y()};
  const double g2 = m.squaredNorm();
  return {std::sqrt(g2) * (gamma.x() * m.y() - gamma.y() * m.x()),
          m.dot(gamma) * m.z() - gamma.z() * g2};
}

AngleSides andoyer_angle_sides_rate(AndoyerAngle a, const Body& body, const Vector3d& omega,
                                    const Vector3d& gamma, const Vector3d& omega_dot,
                                    const Vector3d& gamma_dot) {
  const Vector3d m = body.inertia.cwiseProduct(omega);
  const Vector3d dm = body.inertia.cwiseProduct(omega_dot);
  if (a == AndoyerAngle::l) return {dm.x(), dm.y()};
  const double g = m.norm();
  if (!(g > 0.0)) return {};
  const double m_dm = m.dot(dm);  // ½ (G²)'
  const double p = gamma.x() * m.y() - gamma.y() * m.x();
  const double dp =
      gamma_dot.x() * m.y() + gamma.x() * dm.y() - gamma_dot.y() * m.x() - gamma.y() * dm.x();
  const double h = m.dot(gamma), dh = dm.dot(gamma) + m.dot(gamma_dot);
  return {m_dm / g * p + g * dp,
          dh * m.z() + h * dm.z() - gamma_dot.z() * g * g - 2.0 * gamma.z() * m_dm};
}

}  // namespace epviz::physics
