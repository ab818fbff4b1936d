#pragma once
// The colours of a picture, named once: the job's default colours, the ink
// that reads on the background, the overlay's, and the traffic-light colours
// of the drift readouts (with the drift levels they stand for). Plain values,
// no GL: the painter (src/paint) and the interactive panels (src/live) read
// the same theme, like ImGui's style struct.
#include <optional>
#include <string_view>

#include "scene/frame.hpp"

namespace epviz::scene {

// How a relative drift of an invariant compares with what a picture shows:
// ok near round-off (below 1e-8), warn at picture-level accuracy, bad from
// 1e-2 on, where it would show in the picture (and when it is not a number).
enum class DriftLevel { ok, warn, bad };
constexpr double kDriftWarnFrom = 1e-8;
constexpr double kDriftBadFrom = 1e-2;
DriftLevel drift_level(double relative_drift);

struct Theme {
  std::string_view name;
  bool light = false;  // drawn on a light background
  Colours colours;     // the defaults a job's "colours" override

  // The body: principal axes e1, e2, e3 and their labels, the fixed point and
  // the centre of mass (fill, edge); box edges are the body colour darkened by this factor.
  Rgba axes[3];
  Rgba axis_label;
  Rgba fixed_point_fill, fixed_point_edge;
  Rgba centre_of_mass_fill, centre_of_mass_edge;
  float body_edge_factor;

  // The sphere: its latitude/longitude grid, the pole labels N and S, the edge
  // of the current point's marker, and the caption naming the trail.
  Rgba sphere_grid;
  Rgba pole_label;
  Rgba marker_edge;
  Rgba trail_caption;
  // Trails run along the time colour map from old (0) to new (this, at most 1),
  // fading from opaque (now) to this opacity (the oldest point kept).
  float trail_map_top;
  float trail_oldest_alpha;

  // The Riccati plane's panel, and the mark of a pass through infinity.
  Rgba panel_background, panel_frame, panel_grid, panel_axis, panel_text;
  Rgba infinity_mark, infinity_label;

  // The overlay window: its colour, border and separator, its text (the
  // title's, the lines', the headings'), and its opacity in the panel's
  // column (or without a 3D view) and floating over the 3D view.
  Rgba overlay_window, overlay_border;
  Rgba title, overlay_text, overlay_heading;
  float overlay_alpha_in_column;
  float overlay_alpha_floating;

  // Drift readouts, by level.
  Rgba drift_ok, drift_warn, drift_bad;
  const Rgba& drift_colour(double relative_drift) const;
};

const Theme& dark_theme();   // the default: light lines on a near-black background
const Theme& light_theme();  // dark lines on white, for papers
const Theme& theme(ThemeId id);
std::string_view name(ThemeId id);  // "dark", "light"
std::optional<ThemeId> theme_from_name(std::string_view name);

// Perceived brightness above the middle: text drawn on this colour should be dark.
bool is_light(const Rgba& colour);

}  // namespace epviz::scene
