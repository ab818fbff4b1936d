#include "scene/theme.hpp"

namespace epviz::scene {

DriftLevel drift_level(double d) {
  if (!(d < kDriftBadFrom)) return DriftLevel::bad;
  return d < kDriftWarnFrom ? DriftLevel::ok : DriftLevel::warn;
}

const Rgba& Theme::drift_colour(double d) const {
  switch (drift_level(d)) {
    case DriftLevel::ok: return drift_ok;
    case DriftLevel::warn: return drift_warn;
    case DriftLevel::bad: return drift_bad;
  }
  return drift_bad;
}

bool is_light(const Rgba& c) { return 0.299f * c[0] + 0.587f * c[1] + 0.114f * c[2] > 0.55f; }

const Theme& dark_theme() {
  static const Theme t{
      .name = "dark",
      .light = false,
      .colours = Colours{},
      // Muted red/green/blue, readable on screen and in print.
      .axes = {{0.86f, 0.33f, 0.30f, 1}, {0.36f, 0.74f, 0.40f, 1}, {0.36f, 0.54f, 0.92f, 1}},
      .axis_label = {0.85f, 0.87f, 0.92f, 1},
      .fixed_point_fill = {0.08f, 0.08f, 0.1f, 1},
      .fixed_point_edge = {0.95f, 0.95f, 0.95f, 1},
      .centre_of_mass_fill = {0.98f, 0.85f, 0.25f, 1},
      .centre_of_mass_edge = {0.1f, 0.1f, 0.1f, 1},
      .body_edge_factor = 0.45f,
      .sphere_grid = {0.75f, 0.82f, 0.95f, 0.16f},
      .pole_label = {0.92f, 0.94f, 1.0f, 1},
      .marker_edge = {1, 1, 1, 1},
      .trail_caption = {0.65f, 0.68f, 0.75f, 1},
      .trail_map_top = 1.0f,
      .trail_oldest_alpha = 0.25f,
      .panel_background = {0.10f, 0.11f, 0.13f, 1.0f},
      .panel_frame = {0.45f, 0.47f, 0.52f, 1.0f},
      .panel_grid = {1.0f, 1.0f, 1.0f, 0.07f},
      .panel_axis = {0.75f, 0.77f, 0.82f, 0.8f},
      .panel_text = {0.80f, 0.82f, 0.86f, 1.0f},
      .infinity_mark = {0.95f, 0.3f, 0.3f, 1},
      .infinity_label = {0.95f, 0.35f, 0.35f, 1},
      // ImGui's dark window colours.
      .overlay_window = {0.06f, 0.06f, 0.06f, 0.94f},
      .overlay_border = {0.43f, 0.43f, 0.50f, 0.50f},
      .title = {1.0f, 0.82f, 0.45f, 1.0f},
      .overlay_text = {1.0f, 1.0f, 1.0f, 1.0f},
      .overlay_heading = {0.50f, 0.50f, 0.50f, 1.0f},
      .overlay_alpha_in_column = 0.7f,
      .overlay_alpha_floating = 0.55f,
      .drift_ok = {0.5f, 0.85f, 0.55f, 1},
      .drift_warn = {0.95f, 0.8f, 0.4f, 1},
      .drift_bad = {1.0f, 0.45f, 0.4f, 1},
  };
  return t;
}

const Theme& light_theme() {
  // Every line and label dark enough to read on white (text at 10:1 or more),
  // the body and marker in deeper tones than on black, and a near-opaque
  // light overlay window so that the page stays white.
  static const Theme t{
      .name = "light",
      .light = true,
      .colours = Colours{.background = {1.0f, 1.0f, 1.0f, 1.0f},
                         .body = {0.78f, 0.55f, 0.28f, 1.0f},
                         .sphere = {0.35f, 0.50f, 0.80f, 0.10f},
                         .marker = {0.85f, 0.20f, 0.12f, 1.0f}},
      .axes = {{0.78f, 0.22f, 0.20f, 1}, {0.16f, 0.52f, 0.22f, 1}, {0.20f, 0.38f, 0.80f, 1}},
      .axis_label = {0.2f, 0.2f, 0.25f, 1},
      .fixed_point_fill = {0.08f, 0.08f, 0.1f, 1},
      .fixed_point_edge = {0.95f, 0.95f, 0.95f, 1},
      .centre_of_mass_fill = {0.98f, 0.80f, 0.15f, 1},
      .centre_of_mass_edge = {0.1f, 0.1f, 0.1f, 1},
      .body_edge_factor = 0.45f,
      // 3:1 against the glass where it is most opaque (the outline), as every
      // line and text of this theme (tests/paint/light_theme_contrast_test.cpp).
      .sphere_grid = {0.44f, 0.47f, 0.53f, 1.0f},
      .pole_label = {0.15f, 0.15f, 0.2f, 1},
      .marker_edge = {0.1f, 0.1f, 0.12f, 1},
      .trail_caption = {0.3f, 0.3f, 0.35f, 1},
      // The map's light half (teal to yellow) and faint old points fade on white.
      .trail_map_top = 0.45f,
      .trail_oldest_alpha = 0.6f,
      .panel_background = {0.97f, 0.97f, 0.98f, 1},
      .panel_frame = {0.5f, 0.5f, 0.55f, 1},
      .panel_grid = {0, 0, 0, 0.08f},
      .panel_axis = {0.3f, 0.3f, 0.35f, 0.8f},
      .panel_text = {0.15f, 0.15f, 0.2f, 1},
      .infinity_mark = {0.80f, 0.12f, 0.12f, 1},
      .infinity_label = {0.75f, 0.10f, 0.10f, 1},
      // ImGui's light window, with borders and headings dark enough to print.
      .overlay_window = {0.94f, 0.94f, 0.94f, 1.0f},
      .overlay_border = {0.45f, 0.45f, 0.48f, 1.0f},
      .title = {0.60f, 0.36f, 0.0f, 1.0f},
      .overlay_text = {0.0f, 0.0f, 0.0f, 1.0f},
      .overlay_heading = {0.35f, 0.35f, 0.38f, 1.0f},
      .overlay_alpha_in_column = 0.85f,
      .overlay_alpha_floating = 0.75f,
      .drift_ok = {0.10f, 0.52f, 0.20f, 1},
      .drift_warn = {0.70f, 0.45f, 0.0f, 1},
      .drift_bad = {0.80f, 0.12f, 0.10f, 1},
  };
  return t;
}

const Theme& theme(ThemeId id) {
  switch (id) {
    case ThemeId::dark: return dark_theme();
    case ThemeId::light: return light_theme();
  }
  return dark_theme();
}

std::string_view name(ThemeId id) { return theme(id).name; }

std::optional<ThemeId> theme_from_name(std::string_view name) {
  for (ThemeId id : {ThemeId::dark, ThemeId::light})
    if (theme(id).name == name) return id;
  return std::nullopt;
}

}  // namespace epviz::scene
