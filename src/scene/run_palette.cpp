#include "scene/run_palette.hpp"

#include <array>

namespace epviz::scene {
namespace {

std::size_t slot(int index) { return std::size_t(index < 0 ? 0 : index) % kDistinctRuns; }

}  // namespace

Rgba run_colour(int index, bool light_background) {
  // Sky blue, orange, reddish purple, bluish green, yellow, vermillion (the
  // green after the purple: thin, the blue and the green are told apart less
  // easily than their CIELAB distance says). On a
  // light background the same hues darkened until each reads at 4.5:1 on
  // white (the orange and the yellow become a burnt orange and an ochre).
  static constexpr std::array<Rgba, kDistinctRuns> dark{{{0.34f, 0.71f, 0.91f, 1.0f},
                                                         {0.90f, 0.62f, 0.00f, 1.0f},
                                                         {0.80f, 0.47f, 0.65f, 1.0f},
                                                         {0.00f, 0.62f, 0.45f, 1.0f},
                                                         {0.94f, 0.89f, 0.26f, 1.0f},
                                                         {0.84f, 0.37f, 0.00f, 1.0f}}};
  static constexpr std::array<Rgba, kDistinctRuns> light{{{0.00f, 0.40f, 0.75f, 1.0f},
                                                          {0.80f, 0.30f, 0.00f, 1.0f},
                                                          {0.60f, 0.20f, 0.60f, 1.0f},
                                                          {0.00f, 0.50f, 0.30f, 1.0f},
                                                          {0.55f, 0.45f, 0.00f, 1.0f},
                                                          {0.25f, 0.25f, 0.25f, 1.0f}}};
  return (light_background ? light : dark)[slot(index)];
}

LineStyle run_line_style(int index) {
  static constexpr std::array<LineStyle, kDistinctRuns> styles{
      LineStyle::solid,    LineStyle::dashed,    LineStyle::dotted,
      LineStyle::dash_dot, LineStyle::long_dash, LineStyle::dash_dot_dot};
  return styles[slot(index)];
}

std::string_view name(LineStyle style) {
  switch (style) {
    case LineStyle::solid: return "solid";
    case LineStyle::dashed: return "dashed";
    case LineStyle::dotted: return "dotted";
    case LineStyle::dash_dot: return "dash-dot";
    case LineStyle::long_dash: return "long dash";
    case LineStyle::dash_dot_dot: return "dash-dot-dot";
  }
  return "solid";
}

}  // namespace epviz::scene
