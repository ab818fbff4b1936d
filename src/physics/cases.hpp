#pragma once
// The classical cases of the heavy top as named presets, their defining
// conditions and their fourth integrals (docs/math.md §2.1-2.2). Every fact
// of a case is one entry of the table in physics/case_table.cpp; the
// functions below look it up there.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "physics/body.hpp"

namespace epviz::physics {

// `custom` is a body given without a named case: no conditions, no extra integral.
enum class Case { custom, euler, lagrange, kovalevskaya, goryachev_chaplygin, hess, generic };

// The moment of inertia a fit keeps when the case ties the moments together.
enum class Moment { first, second, third };

// A fourth integral's value and the natural magnitude of its terms (the sum of
// their absolute values, or its analogue), against which its drift is measured.
struct IntegralValue {
  double value = 0.0;
  double magnitude = 0.0;
};

// One row of the case table. The rules are plain functions (nullptr where the
// case has none: generic has no conditions and no fourth integral).
struct CasePreset {
  Case id;
  std::string
      name;  // "euler", "lagrange", "kovalevskaya", "goryachev-chaplygin", "hess", "generic"
  std::string_view alias;            // another spelling read on input ("" if none)
  std::string_view title;            // what a picture calls it: "Kovalevskaya top"
  std::string summary;               // one line: what motion it shows
  std::string conditions;            // human-readable defining conditions
  std::string panel_conditions;      // the same, in words, for the live panel
  std::string extra_integral;        // formula of the fourth integral ("" for generic)
  std::string_view integral_symbol;  // its short name in overlays ("K"; "" for generic)
  Body body;
  InitialState initial;  // satisfies the conditions (and is chaotic for generic)

  // The first condition (body, initial) breaks, as "needs ...; got ...".
  std::optional<std::string> (*broken)(const Body&, const InitialState&) = nullptr;
  // Moves the quantities the conditions tie together so that they hold.
  void (*fit)(Body&, InitialState&, Moment kept) = nullptr;
  // The fourth integral (or invariant relation) at (omega, gamma).
  IntegralValue (*integral)(const Body&, const Vector3d& omega, const Vector3d& gamma) = nullptr;
};

const std::vector<CasePreset>& case_presets();
const CasePreset& preset(Case c);  // throws std::out_of_range for custom
// The case's fourth integral's symbol ("K", "Ω₃"); "" for the generic and custom bodies.
std::string_view integral_symbol(Case c);
std::optional<Case> case_from_name(std::string_view name);
std::string case_name(Case c);  // "custom" for Case::custom

// The first defining condition of `c` that (body, initial) breaks, written for a
// user ("kovalevskaya needs I1 = I2 = 2 I3; got I = (2, 2, 1.5)"), or nullopt.
// Relative tolerance 1e-12 on equalities. Always nullopt for custom and generic.
std::optional<std::string> broken_condition(Case c, const Body& body, const InitialState& initial);

// Makes (body, initial) satisfy case `c`'s conditions by moving the quantities they
// tie to others, keeping moment `kept` where the moments are tied, the weight
// and gamma. Custom and generic are left as they are. Hess needs I1 > I2 > I3 already: no ordering is
// invented, and broken_condition() then still names the break.
void fit_to_case(Case c, Moment kept, Body& body, InitialState& initial);

// The case's fourth integral (or invariant relation H for hess); nullopt for
// custom and generic.
std::optional<double> extra_integral(Case c, const Body& body, const Vector3d& omega,
                                     const Vector3d& gamma);
// The same with the natural magnitude of its terms (physics/invariants.hpp).
std::optional<IntegralValue> extra_integral_terms(Case c, const Body& body, const Vector3d& omega,
                                                  const Vector3d& gamma);

}  // namespace epviz::physics
