#pragma once
// The inverse of a section panel's chart: the states of a level of the two
// integrals every body has (C1, C0) that lie on a section surface and that
// the panel plots at a given point, crossing it in the surface's direction.
// A click on the panel starts an orbit from one of them (the live mode).
//
// Inverted here: a surface gamma_k = c (|c| < 1; not an Andoyer angle) plotted at (gamma_i,
// Omega_k), i != k, in either order, the default chart of a gamma surface
// (gamma3 = 0 at (gamma1, Omega3)). Given those and the surface, gamma is
// known up to the sign of its third component gamma_m (the chart's two
// sheets), and on each sheet the two unknown rates (Omega_i, Omega_m) lie
// on a line (C0, linear in Omega) and an ellipse (C1, quadratic in Omega):
// at most two states a sheet, in closed form. The direction the orbit
// crosses the surface, the sign of d gamma_k / dt = (gamma x Omega)_k,
// chooses among them.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "physics/body.hpp"
#include "physics/level_set.hpp"
#include "sim/section.hpp"

namespace epviz::sim {

// The component whose sign tells the chart's two sheets apart (gamma_m),
// or nullopt when this file cannot invert the chart of `surface` at `coords`.
std::optional<StateComponent> chart_sheet_component(const SectionSurface& surface,
                                                    const std::array<StateComponent, 2>& coords);

struct ChartPreimage {
  // On the surface, at the asked coords, on the level (C0, C1 to 1e-12),
  // |gamma| = 1, crossing in the surface's direction; the most transversal
  // (largest |d gamma_k / dt|) first. Empty where the point has none.
  std::vector<physics::InitialState> states;
  // Why there is none, in words a notice can show ("" when there are states).
  std::string why_none;
};

// The states at the chart point (x, y) (x on coords[0], y on coords[1]).
// `sheet`: +1 or -1 keeps the states whose sheet component has that sign
// (states on the fold, where it is 0, are in both); 0 keeps both sheets.
// Throws std::invalid_argument for a chart chart_sheet_component refuses.
ChartPreimage section_states_at(const physics::Body& body, const physics::Level& level,
                                const SectionSurface& surface,
                                const std::array<StateComponent, 2>& coords, double x, double y,
                                int sheet = 0);

}  // namespace epviz::sim
