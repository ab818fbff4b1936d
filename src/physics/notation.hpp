#pragma once
// The symbols pictures and tables name quantities by, in the notation of
// docs/math.md, each written once: the overlay, the keys, the (a, b) plane's
// panel, the separation chart and the live panel, the atlases' axes and
// legends, the sections' titles and bench's recommendation take them from
// here. It sits in physics, the lowest module all of them link, because these
// are the names of its own quantities. UTF-8; drawn in a font without their
// glyphs (ImGui's bitmap font), a text is spelled in ASCII as a whole
// (render/font_text.hpp: "|γ|²" -> "|gamma|^2").
#include <array>
#include <string_view>

namespace epviz::physics::symbol {

inline constexpr std::string_view gamma = "γ";
inline constexpr std::string_view omega = "Ω";
// Their components, subscripted: a section's surface, an atlas's axis, the
// Lagrange top's fourth integral Ω₃.
inline constexpr std::array<std::string_view, 3> omega_component{"Ω₁", "Ω₂", "Ω₃"};
inline constexpr std::array<std::string_view, 3> gamma_component{"γ₁", "γ₂", "γ₃"};
inline constexpr std::string_view gamma_norm2 = "|γ|²";  // the Casimir |γ|² = 1
inline constexpr std::string_view area = "C₀";           // the area integral
inline constexpr std::string_view energy = "C₁";         // the energy
// The distance of two runs' γ, on the separation chart.
inline constexpr std::string_view separation = "|Δγ|";
// The (a, b) plane's stereographic projection from the south pole (docs/math.md
// (3.1)), the caption of the plane in every picture, rendered or live.
inline constexpr std::string_view riccati_projection = "a = −γ₁/(1+γ₃), b = −γ₂/(1+γ₃)";
// The mark of a pass through infinity on the plane.
inline constexpr std::string_view infinity = "∞";

}  // namespace epviz::physics::symbol
