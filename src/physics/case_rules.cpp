#include "physics/case_rules.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "physics/format.hpp"

namespace epviz::physics::case_rules {

bool equal(double x, double y) {
  return std::abs(x - y) <= kTol * std::max(std::abs(x), std::abs(y));
}

bool negligible(double x, double scale) { return std::abs(x) <= kTol * scale; }

Vector3d unit_from_angles(double theta_deg, double phi_deg) {
  const double t = theta_deg * std::numbers::pi / 180.0, p = phi_deg * std::numbers::pi / 180.0;
  return Vector3d(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
}

std::optional<std::string> moments_tied(const Vector3d& I, double k) {
  if (k == 0.0) {
    if (equal(I.x(), I.y())) return std::nullopt;
    return "needs I1 = I2; got I = " + detail::vec(I);
  }
  if (equal(I.x(), I.y()) && equal(I.x(), k * I.z())) return std::nullopt;
  return "needs I1 = I2 = " + detail::num(k) + " I3; got I = " + detail::vec(I);
}

void tie_moments(Vector3d& I, double k, Moment kept) {
  switch (kept) {
    case Moment::third:
      if (k == 0.0) {
        I.y() = I.x();  // I3 is free
      } else {
        I.x() = I.y() = k * I.z();
      }
      return;
    case Moment::second: I.x() = I.y(); break;
    case Moment::first: I.y() = I.x(); break;
  }
  if (k != 0.0) I.z() = I.x() / k;
}

std::optional<std::string> com_on_axis(const Vector3d& r, int axis, const std::string& condition) {
  const double scale = r.norm();
  for (int i = 0; i < 3; ++i)
    if (i != axis && !negligible(r[i], scale))
      return "needs " + condition + "; got r = " + detail::vec(r);
  return std::nullopt;
}

Vector3d onto_axis(const Vector3d& r, int axis) {
  Vector3d on = Vector3d::Zero();
  on[axis] = r[axis];
  return on;
}

std::optional<std::string> zero_initially(double value, double scale, const std::string& condition,
                                          const char* symbol) {
  if (negligible(value, scale)) return std::nullopt;
  return "needs " + condition + "; got " + symbol + " = " + detail::approx(value);
}

void project_omega(Vector3d& omega, const Vector3d& m) {
  const double mm = m.squaredNorm();
  if (mm > 0.0) omega -= (m.dot(omega) / mm) * m;
}

}  // namespace epviz::physics::case_rules
