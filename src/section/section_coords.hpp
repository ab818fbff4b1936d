#pragma once
// What a section's picture may plot: a component of the state (Ω, γ), or an
// Andoyer–Deprit variable of it (physics/andoyer.hpp, docs/math.md §1.6),
// which needs the body and is undefined on its singular set.
#include <array>
#include <optional>
#include <string_view>
#include <vector>

#include "physics/body.hpp"
#include "sim/section.hpp"

namespace epviz::section {

enum class AndoyerCoord { l, g, L, G, L_over_G };

struct PlotCoord {
  PlotCoord() = default;
  PlotCoord(sim::StateComponent c) : component(c) {}  // NOLINT: a component is a coordinate
  PlotCoord(AndoyerCoord a) : andoyer(a) {}           // NOLINT: so is an Andoyer variable
  sim::StateComponent component = sim::StateComponent::gamma1;
  std::optional<AndoyerCoord> andoyer;  // when set, this instead of `component`
  bool operator==(const PlotCoord&) const = default;
};

// A picture's two axes, x then y. Two state components convert (as
// default_coords gives them), so code that plots components needs no change.
struct PlotCoords : std::array<PlotCoord, 2> {
  PlotCoords() = default;
  PlotCoords(PlotCoord x, PlotCoord y) : std::array<PlotCoord, 2>{x, y} {}
  PlotCoords(const std::array<sim::StateComponent, 2>& c)  // NOLINT: implicit on purpose
      : PlotCoords(c[0], c[1]) {}
};

// Every coordinate: the six components, then "andoyer_l", "andoyer_g",
// "andoyer_L", "andoyer_G", "andoyer_L_over_G".
const std::vector<PlotCoord>& all_plot_coords();
std::string_view name(const PlotCoord& c);
// As figures write it: "γ₁", "Ω₃", "l", "g", "L", "G", "L/G".
std::string_view symbol(const PlotCoord& c);
std::optional<PlotCoord> plot_coord_from_name(std::string_view s);
bool is_andoyer(const PlotCoord& c);

// Its value at (Ω, γ) of `body`; empty for an Andoyer angle on its singular
// set (physics::AndoyerVariables), and for L/G at G = 0.
std::optional<double> value_of(const PlotCoord& c, const physics::Body& body,
                               const physics::Vector3d& omega, const physics::Vector3d& gamma);

}  // namespace epviz::section
