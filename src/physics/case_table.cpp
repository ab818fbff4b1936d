// The case table: every fact of every classical case, one function per case.
// Adding a case is a row here and its enumerator in physics::Case
// (docs/architecture.md §3).
#include <cmath>
#include <optional>
#include <string>

#include "physics/case_rules.hpp"
#include "physics/cases.hpp"
#include "physics/format.hpp"
#include "physics/notation.hpp"

namespace epviz::physics {
namespace {

using namespace case_rules;
using Broken = std::optional<std::string>;

CasePreset euler() {
  CasePreset p;
  p.id = Case::euler;
  p.name = "euler";
  p.title = "Euler top (torque-free)";
  p.integral_symbol = "|L|²";
  p.summary =
      "torque-free body spun near its intermediate axis: periodic flips (tennis racket effect)";
  p.conditions = "r = 0 or P = 0";
  p.panel_conditions = "centre of mass at the fixed point (r = 0)";
  p.extra_integral = "|L|^2 = (I1 Omega1)^2 + (I2 Omega2)^2 + (I3 Omega3)^2";
  p.body = {Vector3d(1, 2, 3), Vector3d(0, 0, 0), 1.0};
  p.initial = {Vector3d(0.2, 3.0, 0.2), unit_from_angles(30, 60)};
  p.broken = [](const Body& b, const InitialState&) -> Broken {
    if (b.weight == 0.0 || std::abs(b.weight) * b.com.norm() <= kTol) return std::nullopt;
    return "needs r = 0 or P = 0 (|P r| <= 1e-12); got r = " + detail::vec(b.com) +
           ", P = " + detail::num(b.weight);
  };
  p.fit = [](Body& b, InitialState&, Moment) { b.com.setZero(); };
  p.integral = [](const Body& b, const Vector3d& w, const Vector3d&) {
    const double l2 = b.inertia.cwiseProduct(w).squaredNorm();
    return IntegralValue{l2, l2};  // all its terms are squares
  };
  return p;
}

CasePreset lagrange() {
  CasePreset p;
  p.id = Case::lagrange;
  p.name = "lagrange";
  p.title = "Lagrange top";
  p.integral_symbol = symbol::omega_component[2];
  p.summary = "symmetric spinning top tilted 30 degrees: slow precession with cusped nutation";
  p.conditions = "I1 = I2, a0 = b0 = 0";
  p.panel_conditions = "I1 = I2, centre of mass on axis 3";
  p.extra_integral = "Omega3";
  p.body = {Vector3d(2, 2, 1), Vector3d(0, 0, 1), 4.0};
  p.initial = {Vector3d(0, 0, 8), unit_from_angles(30, 0)};
  p.broken = [](const Body& b, const InitialState&) -> Broken {
    if (auto m = moments_tied(b.inertia, 0.0)) return m;
    return com_on_axis(b.com, 2, "a0 = b0 = 0 (centre of mass on the symmetry axis)");
  };
  p.fit = [](Body& b, InitialState&, Moment kept) {
    tie_moments(b.inertia, 0.0, kept);
    b.com = onto_axis(b.com, 2);
  };
  p.integral = [](const Body&, const Vector3d& w, const Vector3d&) {
    // Omega3 alone: measured against |Omega| so that Omega3 = 0 still has a scale.
    return IntegralValue{w.z(), w.norm()};
  };
  return p;
}

CasePreset kovalevskaya() {
  CasePreset p;
  p.id = Case::kovalevskaya;
  p.name = "kovalevskaya";
  p.title = "Kovalevskaya top";
  p.integral_symbol = "K";
  p.summary = "Kovalevskaya top: centre of mass in the equatorial plane, quasi-periodic tumbling";
  p.conditions = "I1 = I2 = 2 I3, b0 = 0, c0 = 0";
  p.panel_conditions = "I1 = I2 = 2 I3, centre of mass on axis 1";
  p.extra_integral =
      "K = (Omega1^2 - Omega2^2 - k gamma1)^2 + (2 Omega1 Omega2 - k gamma2)^2, k = P a0 / I3";
  p.body = {Vector3d(2, 2, 1), Vector3d(1, 0, 0), 1.0};
  p.initial = {Vector3d(0.5, 0.3, 1.5), unit_from_angles(60, 30)};
  p.broken = [](const Body& b, const InitialState&) -> Broken {
    if (auto m = moments_tied(b.inertia, 2.0)) return m;
    return com_on_axis(b.com, 0, "b0 = c0 = 0 (centre of mass on the first axis)");
  };
  p.fit = [](Body& b, InitialState&, Moment kept) {
    tie_moments(b.inertia, 2.0, kept);
    b.com = onto_axis(b.com, 0);
  };
  p.integral = [](const Body& b, const Vector3d& w, const Vector3d& g) {
    const double k = b.weight * b.com.x() / b.inertia.z();
    const double x = w.x() * w.x() - w.y() * w.y() - k * g.x();
    const double y = 2.0 * w.x() * w.y() - k * g.y();
    // The same squares with every inner term taken positive.
    const double xm = w.x() * w.x() + w.y() * w.y() + std::abs(k * g.x());
    const double ym = 2.0 * std::abs(w.x() * w.y()) + std::abs(k * g.y());
    return IntegralValue{x * x + y * y, xm * xm + ym * ym};
  };
  return p;
}

CasePreset goryachev_chaplygin() {
  CasePreset p;
  p.id = Case::goryachev_chaplygin;
  p.name = "goryachev-chaplygin";
  p.alias = "goryachev_chaplygin";
  p.title = "Goryachev-Chaplygin top";
  p.integral_symbol = "G";
  p.summary =
      "Goryachev-Chaplygin top on the zero level of the area integral: quasi-periodic motion";
  p.conditions = "I1 = I2 = 4 I3, b0 = c0 = 0, initial C0 = 0";
  p.panel_conditions = "I1 = I2 = 4 I3, centre of mass on axis 1, C0 = 0";
  p.extra_integral = "G = Omega3 (Omega1^2 + Omega2^2) - (P a0 / I3) Omega1 gamma3";
  p.body = {Vector3d(4, 4, 1), Vector3d(1, 0, 0), 1.0};
  const Vector3d g0 = unit_from_angles(50, 20);
  const double w1 = 0.3, w2 = -0.2;
  // C0 = 4 w1 g1 + 4 w2 g2 + w3 g3 = 0
  const double w3 = -(4.0 * w1 * g0.x() + 4.0 * w2 * g0.y()) / g0.z();
  p.initial = {Vector3d(w1, w2, w3), g0};
  p.broken = [](const Body& b, const InitialState& s) -> Broken {
    if (auto m = moments_tied(b.inertia, 4.0)) return m;
    if (auto m = com_on_axis(b.com, 0, "b0 = c0 = 0 (centre of mass on the first axis)")) return m;
    const Vector3d m = b.inertia.cwiseProduct(s.omega);
    return zero_initially(m.dot(s.gamma), m.norm() * s.gamma.norm(),
                          "the initial area integral C0 = I1 Omega1 gamma1 + I2 Omega2 gamma2 + "
                          "I3 Omega3 gamma3 = 0",
                          "C0");
  };
  p.fit = [](Body& b, InitialState& s, Moment kept) {
    tie_moments(b.inertia, 4.0, kept);
    b.com = onto_axis(b.com, 0);
    project_omega(s.omega, b.inertia.cwiseProduct(s.gamma));  // C0 = (I omega) . gamma = 0
  };
  p.integral = [](const Body& b, const Vector3d& w, const Vector3d& g) {
    const double spin = w.z() * (w.x() * w.x() + w.y() * w.y());
    const double tilt = b.weight * b.com.x() / b.inertia.z() * w.x() * g.z();
    return IntegralValue{spin - tilt, std::abs(spin) + std::abs(tilt)};
  };
  return p;
}

// The Hess value of |c0| for given inertia and |a0| (I1 > I2 > I3 assumed).
double hess_c0(const Vector3d& I, double a0) {
  return a0 * std::sqrt(I.x() * (I.y() - I.z())) / std::sqrt(I.z() * (I.x() - I.y()));
}

// The invariant relation H = I1 a0 Omega1 + I3 c0 Omega3 (H = 0 on Hess motions).
IntegralValue hess_relation(const Body& b, const Vector3d& w, const Vector3d&) {
  const double t1 = b.inertia.x() * b.com.x() * w.x(), t3 = b.inertia.z() * b.com.z() * w.z();
  return {t1 + t3, std::abs(t1) + std::abs(t3)};
}

CasePreset hess() {
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
  p.panel_conditions = "I1 > I2 > I3, b0 = 0, c0 = a0 sqrt(I1(I2-I3)/(I3(I1-I2))), H = 0";
  p.extra_integral = "H = I1 a0 Omega1 + I3 c0 Omega3 (invariant relation H = 0)";
  const Vector3d I(3, 2, 1.5);
  const double a0 = 1.0, c0 = hess_c0(I, a0);
  p.body = {I, Vector3d(a0, 0, c0), 1.0};
  // Oscillating (Omega2 changes sign), where the relation H = 0 is stable;
  // in the rotating regime dH/dt = mu H amplifies round-off exponentially.
  const double w3 = 0.6, w1 = -I.z() * c0 * w3 / (I.x() * a0);
  p.initial = {Vector3d(w1, 0.0, w3), unit_from_angles(105, 150)};
  p.broken = [](const Body& b, const InitialState& s) -> Broken {
    const Vector3d& J = b.inertia;
    const Vector3d& r = b.com;
    if (!(J.x() > J.y() && J.y() > J.z())) return "needs I1 > I2 > I3; got I = " + detail::vec(J);
    if (!negligible(r.y(), r.norm())) return "needs b0 = 0; got r = " + detail::vec(r);
    const double c = hess_c0(J, std::abs(r.x()));
    if (!equal(std::abs(r.z()), c))
      return "needs c0 = +-a0 sqrt(I1 (I2 - I3)) / sqrt(I3 (I1 - I2)) = +-" + detail::approx(c) +
             "; got c0 = " + detail::num(r.z()) + " for a0 = " + detail::num(r.x());
    const IntegralValue h = hess_relation(b, s.omega, s.gamma);
    return zero_initially(h.value, h.magnitude,
                          "the initial relation H = I1 a0 Omega1 + I3 c0 Omega3 = 0", "H");
  };
  p.fit = [](Body& b, InitialState& s, Moment) {
    const Vector3d& J = b.inertia;
    Vector3d& r = b.com;
    r.y() = 0.0;
    if (J.x() > J.y() && J.y() > J.z())
      r.z() = (r.z() < 0.0 ? -1.0 : 1.0) * hess_c0(J, std::abs(r.x()));
    project_omega(s.omega, Vector3d(J.x() * r.x(), 0.0, J.z() * r.z()));  // H = 0
  };
  p.integral = hess_relation;
  return p;
}

CasePreset generic() {
  CasePreset p;
  p.id = Case::generic;
  p.name = "generic";
  p.title = "Generic heavy top (chaotic)";
  p.summary = "asymmetric body with an off-axis centre of mass: chaotic tumbling";
  p.conditions = "none";
  p.panel_conditions = "none";
  p.body = {Vector3d(1, 1.7, 2.3), Vector3d(0.6, 0.4, 0.7), 1.0};
  p.initial = {Vector3d(1.0, 0.8, 0.6), unit_from_angles(70, 40)};
  return p;  // no conditions, no fourth integral
}

}  // namespace

const std::vector<CasePreset>& case_presets() {
  static const std::vector<CasePreset> table = {
      euler(), lagrange(), kovalevskaya(), goryachev_chaplygin(), hess(), generic()};
  return table;
}

}  // namespace epviz::physics
