#include "physics/body.hpp"

#include <cmath>

#include "physics/format.hpp"

namespace epviz::physics {

using detail::num;
using detail::vec;

namespace {

bool finite(const Vector3d& v) { return v.allFinite(); }

}  // namespace

void validate_body(const Body& body, bool allow_nonphysical) {
  const Vector3d& I = body.inertia;
  if (!finite(I) || !(I.minCoeff() > 0.0))
    throw InvalidInput("inertia", "inertia must be three positive finite numbers; got " + vec(I));
  if (!finite(body.com))
    throw InvalidInput("com", "centre of mass must be three finite numbers; got " + vec(body.com));
  if (!std::isfinite(body.weight) || body.weight < 0.0)
    throw InvalidInput("weight",
                       "weight must be a non-negative finite number; got " + num(body.weight));
  if (allow_nonphysical) return;
  static const char* const names[3] = {"I1", "I2", "I3"};
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const int lo = i < j ? i : j, hi = i < j ? j : i;
    if (I[lo] + I[hi] < I[k])
      throw InvalidInput("inertia",
                         "inertia " + vec(I) + " breaks the triangle inequality " + names[lo] +
                             " + " + names[hi] + " >= " + names[k] + " (not a rigid body)",
                         Waiver::allow_nonphysical);
  }
}

InitialState validate_initial_state(const InitialState& s, bool normalize) {
  if (!finite(s.omega))
    throw InvalidInput("omega", "omega must be three finite numbers; got " + vec(s.omega));
  if (!finite(s.gamma))
    throw InvalidInput("gamma", "gamma must be three finite numbers; got " + vec(s.gamma));
  const double n = s.gamma.norm();
  if (std::abs(n - 1.0) <= 1e-9) return s;
  if (normalize) {
    if (!(n > 0.0))
      throw InvalidInput("gamma", "gamma = " + vec(s.gamma) +
                                      " is zero and cannot be normalized to a unit vector");
    InitialState out = s;
    out.gamma = s.gamma / n;
    return out;
  }
  throw InvalidInput(
      "gamma",
      "gamma must be a unit vector (| |gamma| - 1 | <= 1e-9); got |gamma| = " + detail::approx(n),
      Waiver::normalize_gamma);
}

}  // namespace epviz::physics
