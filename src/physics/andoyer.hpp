#pragma once
// Andoyer–Deprit variables of the heavy top (docs/math.md §1.6): the angular
// momentum's magnitude G = |M|, its body-axis-3 component L = M3 and its
// vertical component H = M·γ (the area integral C0), with the angles l
// (about the body's third axis) and g (about M) conjugate to L and G. The
// state (Ω, γ) does not fix the angle h about the vertical (the motion's
// symmetry), so it is not computed; on a level of H the reduced motion is
// canonical in (l, L, g, G).
#include <optional>
#include <string_view>

#include "physics/body.hpp"

namespace epviz::physics {

// Where an angle is not defined by the state.
enum class AndoyerSingularity {
  none,
  no_momentum,        // G = 0: no angle
  momentum_on_axis3,  // L = ±G: the body's equator is the invariant plane; l, g undefined
  momentum_vertical,  // H = ±G: the invariant plane is horizontal; g undefined (l is)
};
std::string_view name(AndoyerSingularity s);

// An angle is reported undefined where the sine of the inclination it needs
// (of M to the body's third axis for l and g, of M to the vertical for g) is
// at most this: there the two nodes it is measured between are rounding.
inline constexpr double kAndoyerSingularSine = 1e-9;

struct AndoyerVariables {
  double L = 0.0;  // M3
  double G = 0.0;  // |M|
  double H = 0.0;  // M·γ
  // In (−π, π]; empty on their singular set (`singularity` says which).
  std::optional<double> l, g;
  AndoyerSingularity singularity = AndoyerSingularity::none;
};

// The variables of the state (Ω, γ) of `body` (M = I Ω). γ need not be of
// unit length for the angles (they depend on its direction only); H is M·γ
// as given.
AndoyerVariables andoyer_variables(const Body& body, const Vector3d& omega, const Vector3d& gamma);

// The state with these variables (γ of unit length): the inverse of
// andoyer_variables off the singular set. Throws std::invalid_argument
// unless every number is finite, G > 0, |L| < G and |H| < G.
InitialState andoyer_state(const Body& body, double l, double L, double g, double G, double H);

// The angles a section surface may be a level of (sim/section.hpp).
enum class AndoyerAngle { l, g };

// r sin(angle) and r cos(angle) for a factor r ≥ 0 that vanishes only on
// the angle's singular set: for l, r = |(M1, M2)| (the sides M1, M2); for g,
// r = |γ × M| |(M1, M2)| (the sides G (γ1 M2 − γ2 M1), H L − γ3 G²). Smooth
// in the state away from G = 0 (and polynomial for l), so a section
// `angle = c` is the zero set of sine cos c − cosine sin c where
// sine sin c + cosine cos c > 0, with no jump at ±π.
struct AngleSides {
  double sine = 0.0, cosine = 0.0;
};
AngleSides andoyer_angle_sides(AndoyerAngle a, const Body& body, const Vector3d& omega,
                               const Vector3d& gamma);
// Their time derivatives along a motion through (Ω, γ) with rates
// (omega_dot, gamma_dot); zero at G = 0.
AngleSides andoyer_angle_sides_rate(AndoyerAngle a, const Body& body, const Vector3d& omega,
                                    const Vector3d& gamma, const Vector3d& omega_dot,
                                    const Vector3d& gamma_dot);

}  // namespace epviz::physics
