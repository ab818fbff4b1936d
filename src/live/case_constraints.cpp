#include "live/case_constraints.hpp"

#include <cmath>

namespace epviz::live {
namespace {

using physics::Vector3d;

// I1 = I2 = k I3, keeping the moment the user edited.
void tie_moments(Vector3d& I, double k, Edited edited) {
  switch (edited) {
    case Edited::inertia_3: I.x() = I.y() = k * I.z(); break;
    case Edited::inertia_2:
      I.x() = I.y();
      I.z() = I.y() / k;
      break;
    case Edited::inertia_1:
    case Edited::com:
    case Edited::weight:
    case Edited::omega:
    case Edited::gamma:
      I.y() = I.x();
      I.z() = I.x() / k;
      break;
  }
}

// Removes the component of omega along m, so that m . omega = 0 (a linear
// condition on the initial state: C0 = 0 for Goryachev-Chaplygin, H = 0 for Hess).
void project_omega(Vector3d& omega, const Vector3d& m) {
  const double mm = m.squaredNorm();
  if (mm > 0.0) omega -= (m.dot(omega) / mm) * m;
}

}  // namespace

void enforce_case(physics::Case c, Edited edited, physics::Body& body, physics::InitialState& s) {
  Vector3d& I = body.inertia;
  Vector3d& r = body.com;
  switch (c) {
    case physics::Case::custom:
    case physics::Case::generic: return;
    case physics::Case::euler: r.setZero(); return;
    case physics::Case::lagrange:
      if (edited == Edited::inertia_2)
        I.x() = I.y();
      else
        I.y() = I.x();
      r = Vector3d(0.0, 0.0, r.z());
      return;
    case physics::Case::kovalevskaya:
      tie_moments(I, 2.0, edited);
      r = Vector3d(r.x(), 0.0, 0.0);
      return;
    case physics::Case::goryachev_chaplygin:
      tie_moments(I, 4.0, edited);
      r = Vector3d(r.x(), 0.0, 0.0);
      project_omega(s.omega, I.cwiseProduct(s.gamma));  // C0 = (I omega) . gamma = 0
      return;
    case physics::Case::hess: {
      r.y() = 0.0;
      if (I.x() > I.y() && I.y() > I.z()) {
        const double ratio =
            std::sqrt(I.x() * (I.y() - I.z())) / std::sqrt(I.z() * (I.x() - I.y()));
        r.z() = (r.z() < 0.0 ? -1.0 : 1.0) * std::abs(r.x()) * ratio;
      }
      project_omega(s.omega,
                    Vector3d(I.x() * r.x(), 0.0, I.z() * r.z()));  // H = I1 a0 w1 + I3 c0 w3 = 0
      return;
    }
  }
}

const char* case_conditions_summary(physics::Case c) {
  switch (c) {
    case physics::Case::euler: return "centre of mass at the fixed point (r = 0)";
    case physics::Case::lagrange: return "I1 = I2, centre of mass on axis 3";
    case physics::Case::kovalevskaya: return "I1 = I2 = 2 I3, centre of mass on axis 1";
    case physics::Case::goryachev_chaplygin:
      return "I1 = I2 = 4 I3, centre of mass on axis 1, C0 = 0";
    case physics::Case::hess:
      return "I1 > I2 > I3, b0 = 0, c0 = a0 sqrt(I1(I2-I3)/(I3(I1-I2))), H = 0";
    case physics::Case::generic:
    case physics::Case::custom: break;
  }
  return "none";
}

}  // namespace epviz::live
