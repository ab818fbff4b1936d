#pragma once
// The words of an atlas figure (sweep/atlas.hpp): its axes named by their
// symbols, what its colour means with a unit, and the caption that says how
// the runs behind it were made. Maps compare only at equal end time, method
// and accuracy, so the caption names them.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "sweep/sweep_spec.hpp"

namespace epviz::sweep {

// "gamma[0]" -> "γ₁", "omega[2]" -> "Ω₃", "energy" -> "C₁" (the energy's symbol in physics/notation.hpp), "t_end" -> "T";
// other fields by their own name.
std::string axis_symbol(const std::string& field);

// An axis's title: its symbol ("energy C₁" and "end time T" with their
// names, which a reader might not guess from one letter), and for a component of γ that the runs
// rescaled to a unit vector (normalize_gamma: their initial γ differs from
// the axis's value) "γ₁ before normalisation", since that is what the axis holds.
std::string axis_title(const std::string& field, const std::vector<const nlohmann::json*>& rows);

// What a metric's colour means, with its unit where it has one:
// "ftle" -> "largest FTLE λ (1/time)". The range of the fourth integral is
// named by the symbol of the one case that `rows` ran ("K" for the
// Kovalevskaya top, "Ω₃" for Lagrange's, from the case table), and in words
// ("the case's fourth integral") when the rows name no such case or several.
std::string metric_label(const std::string& metric,
                         const std::vector<const nlohmann::json*>& rows = {});

// One line under the map: the end time T (always: "T = 50", or its range
// when an axis varies it), the method and its tol or step (those the rows
// share: one that varies is an axis), and for the ftle metric always the
// window and separation of `ftle` (not in the rows; said to be unknown
// without it). "T = 50, method gauss4, tol = 1e-10; FTLE window 0.5, separation 1e-08".
// For chaotic_share it also counts the orbits above the threshold that the
// share leaves out (sweep/level_point.hpp): hyperbolic ones, which kept the
// case's fourth integral, and undecided ones.
std::string atlas_caption(const std::vector<const nlohmann::json*>& rows, const std::string& metric,
                          const std::optional<FtleSettings>& ftle);

}  // namespace epviz::sweep
