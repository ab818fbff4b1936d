#pragma once
// The pieces the case table (physics/case_table.cpp) writes its rows' rules
// with: the tolerance of the defining equalities, the checks every case
// words the same way, and the moves that restore a tie.
#include <optional>
#include <string>

#include "physics/body.hpp"
#include "physics/cases.hpp"

namespace epviz::physics::case_rules {

inline constexpr double kTol = 1e-12;  // relative tolerance on the defining equalities

bool equal(double x, double y);
// |x| negligible against `scale` (x = 0 exactly when scale = 0).
bool negligible(double x, double scale);

// Unit vector from polar angle theta (from the body's third axis) and azimuth
// phi, both in degrees: unit to round-off.
Vector3d unit_from_angles(double theta_deg, double phi_deg);

// "needs I1 = I2 = k I3; got I = (...)" (k = 0: I1 = I2 only, I3 free), or nullopt.
std::optional<std::string> moments_tied(const Vector3d& I, double k);
// I1 = I2 = k I3 (k = 0: I1 = I2 only), keeping the moment `kept`.
void tie_moments(Vector3d& I, double k, Moment kept);

// "needs <condition>; got r = (...)" unless the centre of mass lies on body
// axis `axis` (0, 1 or 2) to round-off; nullopt when it does.
std::optional<std::string> com_on_axis(const Vector3d& r, int axis, const std::string& condition);
// The centre of mass moved onto body axis `axis`, its component there kept.
Vector3d onto_axis(const Vector3d& r, int axis);

// "needs <condition>; got C = <value>" for a linear condition m . omega = 0 on
// the initial state whose terms have magnitude `scale`, or nullopt.
std::optional<std::string> zero_initially(double value, double scale, const std::string& condition,
                                          const char* symbol);
// Removes the component of omega along m, so that m . omega = 0 afterwards.
void project_omega(Vector3d& omega, const Vector3d& m);

}  // namespace epviz::physics::case_rules
