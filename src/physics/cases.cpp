#include "physics/cases.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "physics/format.hpp"

namespace epviz::physics {

using detail::approx;
using detail::num;
using detail::vec;

namespace {

constexpr double kTol = 1e-12;  // relative tolerance on the defining equalities

// Unit vector from polar angle theta (from the body's third axis) and azimuth
// phi, both in degrees: unit to round-off.
Vector3d unit_from_angles(double theta_deg, double phi_deg) {
  const double t = theta_deg * std::numbers::pi / 180.0, p = phi_deg * std::numbers::pi / 180.0;
  return Vector3d(std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t));
}

bool equal(double x, double y) {
  return std::abs(x - y) <= kTol * std::max(std::abs(x), std::abs(y));
}
// |x| negligible against `scale` (x = 0 exactly when scale = 0).
bool negligible(double x, double scale) { return std::abs(x) <= kTol * scale; }

// The Hess value of |c0| for given inertia and a0 (I1 > I2 > I3 assumed).
double hess_c0(const Vector3d& I, double a0) {
  return a0 * std::sqrt(I.x() * (I.y() - I.z())) / std::sqrt(I.z() * (I.x() - I.y()));
}

double area(const Body& body, const InitialState& s) {
  return body.inertia.cwiseProduct(s.omega).dot(s.gamma);
}

std::vector<CasePreset> make_presets() {
  std::vector<CasePreset> v;
  {
    CasePreset p;
    p.id = Case::euler;
    p.name = "euler";
    p.title = "Euler top (torque-free)";
    p.integral_symbol = "|L|^2";
    p.summary =
        "torque-free body spun near its intermediate axis: periodic flips (tennis racket effect)";
    p.conditions = "r = 0 or P = 0";
    p.extra_integral = "|L|^2 = (I1 Omega1)^2 + (I2 Omega2)^2 + (I3 Omega3)^2";
    p.body = {Vector3d(1, 2, 3), Vector3d(0, 0, 0), 1.0};
    p.initial = {Vector3d(0.2, 3.0, 0.2), unit_from_angles(30, 60)};
    v.push_back(p);
  }
  {
    CasePreset p;
    p.id = Case::lagrange;
    p.name = "lagrange";
    p.title = "Lagrange top";
    p.integral_symbol = "Omega3";
    p.summary = "symmetric spinning top tilted 30 degrees: slow precession with cusped nutation";
    p.conditions = "I1 = I2, a0 = b0 = 0";
    p.extra_integral = "Omega3";
    p.body = {Vector3d(2, 2, 1), Vector3d(0, 0, 1), 4.0};
    p.initial = {Vector3d(0, 0, 8), unit_from_angles(30, 0)};
    v.push_back(p);
  }
  {
    CasePreset p;
    p.id = Case::kovalevskaya;
    p.name = "kovalevskaya";
    p.title = "Kovalevskaya top";
    p.integral_symbol = "K";
    p.summary = "Kovalevskaya top: centre of mass in the equatorial plane, quasi-periodic tumbling";
    p.conditions = "I1 = I2 = 2 I3, b0 = 0, c0 = 0";
    p.extra_integral =
        "K = (Omega1^2 - Omega2^2 - k gamma1)^2 + (2 Omega1 Omega2 - k gamma2)^2, k = P a0 / I3";
    p.body = {Vector3d(2, 2, 1), Vector3d(1, 0, 0), 1.0};
    p.initial = {Vector3d(0.5, 0.3, 1.5), unit_from_angles(60, 30)};
    v.push_back(p);
  }
  {
    CasePreset p;
    p.id = Case::goryachev_chaplygin;
    p.name = "goryachev-chaplygin";
    p.title = "Goryachev-Chaplygin top";
    p.integral_symbol = "G";
    p.summary =
        "Goryachev-Chaplygin top on the zero level of the area integral: quasi-periodic motion";
    p.conditions = "I1 = I2 = 4 I3, b0 = c0 = 0, initial C0 = 0";
    p.extra_integral = "G = Omega3 (Omega1^2 + Omega2^2) - (P a0 / I3) Omega1 gamma3";
    p.body = {Vector3d(4, 4, 1), Vector3d(1, 0, 0), 1.0};
    const Vector3d g = unit_from_angles(50, 20);
    const double w1 = 0.3, w2 = -0.2;
    // C0 = 4 w1 g1 + 4 w2 g2 + w3 g3 = 0
    const double w3 = -(4.0 * w1 * g.x() + 4.0 * w2 * g.y()) / g.z();
    p.initial = {Vector3d(w1, w2, w3), g};
    v.push_back(p);
  }
  {
    CasePreset p;
    p.id = Case::hess;
    p.name = "hess";
    p.title = "Hess top";
    p.integral_symbol = "H";
    p.summary =
        "Hess motion: on the invariant relation H = 0 the body swings like a pendulum about its "
        "lowest position";
    p.conditions =
        "I1 > I2 > I3, b0 = 0, c0 = +-a0 sqrt(I1 (I2 - I3)) / sqrt(I3 (I1 - I2)), initial H = 0";
    p.extra_integral = "H = I1 a0 Omega1 + I3 c0 Omega3 (invariant relation H = 0)";
    const Vector3d I(3, 2, 1.5);
    const double a0 = 1.0, c0 = hess_c0(I, a0);
    p.body = {I, Vector3d(a0, 0, c0), 1.0};
    // Oscillating (Omega2 changes sign), where the relation H = 0 is stable;
    // in the rotating regime dH/dt = mu H amplifies round-off exponentially.
    const double w3 = 0.6, w1 = -I.z() * c0 * w3 / (I.x() * a0);
    p.initial = {Vector3d(w1, 0.0, w3), unit_from_angles(105, 150)};
    v.push_back(p);
  }
  {
    CasePreset p;
    p.id = Case::generic;
    p.name = "generic";
    p.title = "Generic heavy top (chaotic)";
    p.integral_symbol = "";
    p.summary = "asymmetric body with an off-axis centre of mass: chaotic tumbling";
    p.conditions = "none";
    p.extra_integral = "";
    p.body = {Vector3d(1, 1.7, 2.3), Vector3d(0.6, 0.4, 0.7), 1.0};
    p.initial = {Vector3d(1.0, 0.8, 0.6), unit_from_angles(70, 40)};
    v.push_back(p);
  }
  return v;
}

}  // namespace

const std::vector<CasePreset>& case_presets() {
  static const std::vector<CasePreset> presets = make_presets();
  return presets;
}

const CasePreset& preset(Case c) {
  for (const CasePreset& p : case_presets())
    if (p.id == c) return p;
  throw std::out_of_range("no preset for case '" + case_name(c) + "'");
}

std::string case_name(Case c) {
  switch (c) {
    case Case::custom: return "custom";
    case Case::euler: return "euler";
    case Case::lagrange: return "lagrange";
    case Case::kovalevskaya: return "kovalevskaya";
    case Case::goryachev_chaplygin: return "goryachev-chaplygin";
    case Case::hess: return "hess";
    case Case::generic: return "generic";
  }
  return "custom";
}

std::optional<Case> case_from_name(std::string_view name) {
  static constexpr Case all[] = {
      Case::custom, Case::euler,  Case::lagrange, Case::kovalevskaya, Case::goryachev_chaplygin,
      Case::hess,   Case::generic};
  for (Case c : all)
    if (name == case_name(c)) return c;
  if (name == "goryachev_chaplygin") return Case::goryachev_chaplygin;
  return std::nullopt;
}

std::optional<std::string> broken_condition(Case c, const Body& body, const InitialState& s) {
  const Vector3d& I = body.inertia;
  const Vector3d& r = body.com;
  const double P = body.weight;
  const std::string n = case_name(c);
  switch (c) {
    case Case::custom:
    case Case::generic: return std::nullopt;
    case Case::euler:
      if (P == 0.0 || std::abs(P) * r.norm() <= kTol) return std::nullopt;
      return n + " needs r = 0 or P = 0 (|P r| <= 1e-12); got r = " + vec(r) + ", P = " + num(P);
    case Case::lagrange:
      if (!equal(I.x(), I.y())) return n + " needs I1 = I2; got I = " + vec(I);
      if (!negligible(r.x(), r.norm()) || !negligible(r.y(), r.norm()))
        return n + " needs a0 = b0 = 0 (centre of mass on the symmetry axis); got r = " + vec(r);
      return std::nullopt;
    case Case::kovalevskaya:
      if (!equal(I.x(), I.y()) || !equal(I.x(), 2.0 * I.z()))
        return n + " needs I1 = I2 = 2 I3; got I = " + vec(I);
      if (!negligible(r.y(), r.norm()) || !negligible(r.z(), r.norm()))
        return n + " needs b0 = 0 and c0 = 0 (centre of mass on the first axis); got r = " + vec(r);
      return std::nullopt;
    case Case::goryachev_chaplygin: {
      if (!equal(I.x(), I.y()) || !equal(I.x(), 4.0 * I.z()))
        return n + " needs I1 = I2 = 4 I3; got I = " + vec(I);
      if (!negligible(r.y(), r.norm()) || !negligible(r.z(), r.norm()))
        return n + " needs b0 = c0 = 0 (centre of mass on the first axis); got r = " + vec(r);
      const double c0 = area(body, s);
      const double scale = I.cwiseProduct(s.omega).norm() * s.gamma.norm();
      if (!negligible(c0, scale))
        return n +
               " needs the initial area integral C0 = I1 Omega1 gamma1 + I2 Omega2 gamma2 + "
               "I3 Omega3 gamma3 = 0; got C0 = " +
               approx(c0);
      return std::nullopt;
    }
    case Case::hess: {
      if (!(I.x() > I.y() && I.y() > I.z())) return n + " needs I1 > I2 > I3; got I = " + vec(I);
      if (!negligible(r.y(), r.norm())) return n + " needs b0 = 0; got r = " + vec(r);
      const double c0 = hess_c0(I, std::abs(r.x()));
      if (!equal(std::abs(r.z()), c0))
        return n + " needs c0 = +-a0 sqrt(I1 (I2 - I3)) / sqrt(I3 (I1 - I2)) = +-" + approx(c0) +
               "; got c0 = " + num(r.z()) + " for a0 = " + num(r.x());
      const double t1 = I.x() * r.x() * s.omega.x(), t3 = I.z() * r.z() * s.omega.z();
      if (!negligible(t1 + t3, std::abs(t1) + std::abs(t3)))
        return n + " needs the initial relation H = I1 a0 Omega1 + I3 c0 Omega3 = 0; got H = " +
               approx(t1 + t3);
      return std::nullopt;
    }
  }
  return std::nullopt;
}

std::optional<double> extra_integral(Case c, const Body& body, const Vector3d& w,
                                     const Vector3d& g) {
  const Vector3d& I = body.inertia;
  const double P = body.weight, a0 = body.com.x(), c0 = body.com.z();
  switch (c) {
    case Case::custom:
    case Case::generic: return std::nullopt;
    case Case::euler: return I.cwiseProduct(w).squaredNorm();
    case Case::lagrange: return w.z();
    case Case::kovalevskaya: {
      const double k = P * a0 / I.z();
      const double x = w.x() * w.x() - w.y() * w.y() - k * g.x();
      const double y = 2.0 * w.x() * w.y() - k * g.y();
      return x * x + y * y;
    }
    case Case::goryachev_chaplygin:
      return w.z() * (w.x() * w.x() + w.y() * w.y()) - P * a0 / I.z() * w.x() * g.z();
    case Case::hess: return I.x() * a0 * w.x() + I.z() * c0 * w.z();
  }
  return std::nullopt;
}

}  // namespace epviz::physics
