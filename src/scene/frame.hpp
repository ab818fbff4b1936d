#pragma once
// What one frame shows, as plain values: the scene module fills it from the
// simulation, the painter (src/paint) draws it. No GL here, and the painter
// needs no physics to read it.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/cloud.hpp"  // the cloud
#include "scene/layers.hpp"

namespace epviz::scene {

using Rgba = std::array<float, 4>;  // sRGB 0..1 as in "#rrggbb", straight alpha

enum class View {
  body,   // body axes fixed on screen; gamma (the vertical seen from the body) moves
  space,  // the vertical fixed (z up); the body turns, precesses and nutates
};

struct CameraSettings {
  double azimuth_deg = 35.0;    // about the z axis, from +x towards +y
  double elevation_deg = 22.0;  // above the xy plane
  double distance = 3.4;        // in units of the sphere radius
};

// How a run's line is drawn in a comparison scene (scene/run_palette.hpp).
enum class LineStyle { solid, dashed, dotted, dash_dot, long_dash, dash_dot_dot };

// The named colour sets (scene/theme.hpp); a job's own colours override a theme's defaults.
enum class ThemeId { dark, light };

struct Colours {
  Rgba background{0.06f, 0.07f, 0.09f, 1.0f};
  Rgba body{0.80f, 0.62f, 0.36f, 1.0f};
  Rgba sphere{0.55f, 0.70f, 0.95f, 0.16f};
  Rgba marker{1.0f, 0.35f, 0.25f, 1.0f};  // the current point on sphere and plane
};

// A point of a trail; `age` in [0, 1]: 0 is now, 1 the oldest point kept.
// Trails are coloured by age on one time colour map, shared by sphere and plane.
struct TrailPoint {
  Eigen::Vector3f p;
  float age;
};

struct PlanePoint {
  Eigen::Vector2f ab;
  float age;
  bool break_before = false;  // do not join to the previous point (the path went through infinity)
};

// Where the (a, b) path leaves or re-enters the panel's range, or passes
// through infinity (gamma near the south pole, a chart switch in the Riccati
// formulation): shown as marks, never clipped silently.
struct PlaneMark {
  enum class Kind { leaves_panel, enters_panel, through_infinity };
  Eigen::Vector2f ab;  // on the panel's border for leaves/enters
  Kind kind;
  float age;
};

// The body drawn as the uniform box with the same principal moments.
struct BodyShape {
  Eigen::Vector3f half_extents;    // along body axes 1, 2, 3, scaled to fit the sphere
  Eigen::Vector3f centre_of_mass;  // body axes, same scale; zero when r = 0
};

struct OverlayText {
  std::string title;  // e.g. "Kovalevskaya top"
  // Time, method and tolerance, formulation, parameters: most important first,
  // so that a small picture can show only the first few.
  std::vector<std::string> lines;
  // Running relative drift of each invariant: (name, value) e.g. ("C₁ (energy)", 3e-13),
  // measured on the states drawn (interpolated between the integrator's steps).
  std::vector<std::pair<std::string, double>> drifts;
  // The same invariants' drift at the integrator's own steps, one per row of
  // `drifts`, where the run measures it (empty: not known; the overlay then
  // shows the drawn states' column alone).
  std::vector<double> step_drifts;
};

// One run of a comparison scene beyond the first (the first run's trail,
// current point and path are the single-run fields of Frame): drawn in its
// own colour, its body as a ghost marker.
struct RunTrace {
  std::vector<TrailPoint> trail;
  Eigen::Vector3f current = Eigen::Vector3f::UnitZ();
  std::vector<PlanePoint> plane_path;
  std::vector<PlaneMark> plane_marks;
  std::optional<Eigen::Vector2f> plane_current;
  // Separation of this run's gamma from the first run's, |delta gamma|, at the
  // samples so far: (t, separation).
  std::vector<Eigen::Vector2f> separation;
  std::optional<double> pixel_true_until;  // as Frame::pixel_true_until, for this run
  std::optional<float> untrue_age;
};

// How a picture sets its type and arranges its parts. A screen picture sizes
// its text, lines and paddings from its height and puts the panels beside the
// 3D view; a figure at a printed size (`--figure-width`, io::PrintSize) sizes
// them from the font asked for and stacks its parts in one column (the 3D
// view, the legend, the overlay's text, the panels), so that a column of a
// journal holds it with its text at the size asked.
// Where the overlay's window goes on a screen picture (a job's
// "overlay_place"): `automatic` puts it in the panel column above the plot
// where the plot keeps room, else over the 3D view's left edge clear of the
// runs' current points; `beside` always in the column (the plot smaller);
// a corner over the 3D view. A stacked page gives it a band of its own.
enum class OverlayPlace { automatic, beside, top_left, top_right, bottom_left, bottom_right };
// "auto", "beside", "top-left", "top-right", "bottom-left", "bottom-right".
std::string_view name(OverlayPlace place);
std::optional<OverlayPlace> overlay_place_from_name(std::string_view name);
inline bool is_corner(OverlayPlace p) {
  return p != OverlayPlace::automatic && p != OverlayPlace::beside;
}

struct PageLayout {
  // The picture height whose type this picture uses (overlay_font_px and
  // ui_scale of it); 0: its own height.
  int type_height = 0;
  bool stacked = false;
  OverlayPlace overlay = OverlayPlace::automatic;
  int type_height_for(int height) const { return type_height > 0 ? type_height : height; }
};

// What a comparison scene (a job's "runs") adds to a frame.
struct Comparison {
  // Legend rows, one per run, the first run first: "rk4, step 0.2".
  std::vector<std::string> labels;
  std::vector<Rgba> colours;     // one per run: a qualitative palette (scene/run_palette.hpp)
  std::vector<LineStyle> lines;  // one per run, as distinct as the colours
  std::vector<RunTrace> others;  // runs 2, 3, ...
  double t_end = 0.0;            // the separation chart's time axis
};

// A Poincaré section panel (a job's "section"): every crossing of the
// section surface up to the frame's time, a dot per crossing in its run's
// colour. Plain values: scene/section_panel.hpp finds the crossings.
struct SectionPanel {
  std::string title;                // the surface: "γ₃ = 0, upward"
  std::array<std::string, 2> axes;  // the coordinates' symbols: "γ₁", "Ω₃"
  // The plot's range, x then y: every crossing of the whole run with a
  // margin, the same in every frame so that the dots stay put as it fills.
  std::array<double, 4> range{-1.0, 1.0, -1.0, 1.0};
  std::vector<std::vector<Eigen::Vector2d>> runs;  // per run, first run first, oldest first
  std::vector<Rgba> colours;                       // one per run
  // Crossings up to the frame's time on the sheet not shown (a job's
  // section.sheet), and the panel's note saying so ("" when none).
  std::size_t hidden = 0;
  std::string note;
};

struct Frame {
  int index = 0;
  double t = 0.0;
  View view = View::body;
  Layers layers;
  CameraSettings camera;
  ThemeId theme = ThemeId::dark;
  Colours colours;

  // Body -> screen-world rotation of the body. Body view: identity. Space view:
  // the attitude (world z is the vertical).
  Eigen::Quaternionf body_rotation = Eigen::Quaternionf::Identity();
  BodyShape body;

  // Sphere layer. Body view: gamma in body axes. Space view: body axis 3 in
  // space (the apex trace). `current` is the newest point.
  std::vector<TrailPoint> trail;
  Eigen::Vector3f current = Eigen::Vector3f::UnitZ();
  std::string trail_label;  // "γ (body frame)" or "body axis 3 (space frame)"
  double trail_time = 0.0;  // simulation time from age 0 to age 1 (the colour bar's span); 0: none

  // Riccati plane: stereographic (a, b) of gamma; the panel shows
  // [-plane_extent, plane_extent]^2 with the unit circle (the equator).
  float plane_extent = 2.5f;
  std::vector<PlanePoint> plane_path;
  std::vector<PlaneMark> plane_marks;
  std::optional<Eigen::Vector2f>
      plane_current;  // empty when gamma is at the south pole or off the panel

  OverlayText overlay;

  // The time after which the (first) run's drawn trajectory may differ from
  // the true one by more than half a pixel (sim error estimated against a
  // shadow run): empty while it is pixel-true. The painter draws the trail
  // after it thinner and dashed, in the same colours, and says so.
  std::optional<double> pixel_true_until;
  std::optional<float> untrue_age;  // trail points newer than this age lie after it
  // What the overlay says of it: "beyond t = 41.7: not pixel-accurate (chaos)".
  std::string pixel_true_note;

  std::optional<Comparison> comparison;  // comparison scenes only
  std::optional<CloudFrame> cloud;       // jobs with a "cloud" only
  std::optional<SectionPanel> section;   // jobs with a "section" only

  // A line under the picture naming what it shows (gallery tiles); empty: none.
  std::string caption;
  PageLayout page;  // SceneSettings::page
};

}  // namespace epviz::scene
