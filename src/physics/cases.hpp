#pragma once
// The classical cases of the heavy top as named presets, their defining
// conditions and their fourth integrals (docs/math.md §2.1-2.2).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "physics/body.hpp"

namespace epviz::physics {

// `custom` is a body given without a named case: no conditions, no extra integral.
enum class Case { custom, euler, lagrange, kovalevskaya, goryachev_chaplygin, hess, generic };

struct CasePreset {
  Case id;
  std::string
      name;  // "euler", "lagrange", "kovalevskaya", "goryachev-chaplygin", "hess", "generic"
  std::string_view title;            // what a picture calls it: "Kovalevskaya top"
  std::string summary;               // one line: what motion it shows
  std::string conditions;            // human-readable defining conditions
  std::string extra_integral;        // formula of the fourth integral ("" for generic)
  std::string_view integral_symbol;  // its short name in overlays ("K"; "" for generic)
  Body body;
  InitialState initial;  // satisfies the conditions (and is chaotic for generic)
};

const std::vector<CasePreset>& case_presets();
const CasePreset& preset(Case c);  // throws std::out_of_range for custom
std::optional<Case> case_from_name(std::string_view name);
std::string case_name(Case c);  // "custom" for Case::custom

// The first defining condition of `c` that (body, initial) breaks, written for a
// user ("kovalevskaya needs I1 = I2 = 2 I3; got I = (2, 2, 1.5)"), or nullopt.
// Relative tolerance 1e-12 on equalities. Always nullopt for custom and generic.
std::optional<std::string> broken_condition(Case c, const Body& body, const InitialState& initial);

// The case's fourth integral (or invariant relation H for hess); nullopt for
// custom and generic.
std::optional<double> extra_integral(Case c, const Body& body, const Vector3d& omega,
                                     const Vector3d& gamma);

}  // namespace epviz::physics
