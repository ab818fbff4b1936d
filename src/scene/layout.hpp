#pragma once
// Where each part of a picture goes, and how many pixels a unit of gamma or of
// (a, b) covers there: one computation for the painter (which draws into these
// rectangles) and for the plan (which picks the tolerance and the trail's
// decimation from the pixel scales). Plain integers, no GL.
#include <optional>

#include "scene/frame.hpp"

namespace epviz::scene {

// Pixels, origin at the top left (the painter's viewports use the same convention).
struct Rect {
  int x = 0, y = 0, width = 0, height = 0;
  int right() const { return x + width; }
  int bottom() const { return y + height; }
};

// What the overlay window holds: text lines (before the height cut, see
// overlay_lines_shown) and drift rows.
struct OverlayShape {
  int lines = 0;
  int drifts = 0;
};
OverlayShape overlay_shape(const OverlayText& overlay);
// The overlay the layout keeps room for, whatever a frame's overlay holds:
// five lines and four drift rows (FrameSource's), so that the panel has the
// same rectangle in every job.
constexpr OverlayShape kOverlayReserved{5, 4};

struct LayoutRequest {
  int width = 1280, height = 720;
  Layers layers;
  OverlayShape overlay;          // informative only: the layout reserves kOverlayReserved
  double camera_distance = 3.4;  // sphere radii (CameraSettings::distance)
  float plane_extent = 2.5f;     // the panel shows [-extent, extent]^2
  int reserved_left = 0;         // kept free at the left edge (interactive panels)
  int chart_height = 0;          // comparison scenes: the separation chart under the plot
  int legend_rows = 0;           // comparison scenes: the legend's rows (comparison_legend_rows)
  bool caption = false;          // a caption line across the top (gallery tiles)
  // A section panel (Frame::section) beside the Riccati plane: the column
  // takes half the width, and its plots sit side by side.
  bool section_panel = false;
  PageLayout page;  // the type's size and whether the parts stack (Frame::page)
};

struct FrameLayout {
  std::optional<Rect> view_3d;       // body and sphere
  std::optional<Rect> panel_column;  // the Riccati panel's column
  std::optional<Rect> plot_area;     // the panel's square plot inside its column
  std::optional<Rect> chart_area;    // comparison scenes: under the plot (paint/separation_chart)
  // Comparison scenes: the legend's strip under the 3D view (or under the
  // panel without one), clear of the sphere and of every mark.
  std::optional<Rect> legend_area;
  std::optional<Rect> caption_area;  // the caption's line across the top
  std::optional<Rect> section_area;  // the section panel's square plot, right of the plane's
  bool overlay_in_column = false;    // the overlay sits above the plot (else over the 3D view)
  // A stacked page: the overlay's own band across the page, between the 3D
  // view (with its legend) and the panels.
  std::optional<Rect> overlay_area;
  // Pixels per unit of gamma at the sphere's centre, and per unit of a or b in
  // the plot; 0 where the picture has no such part.
  double sphere_px_per_unit = 0.0;
  double plane_px_per_unit = 0.0;
};

FrameLayout frame_layout(const LayoutRequest& request);
// The height a stacked page of the request's width needs for its parts
// (request.height is not read): what a figure at a printed size is given.
int stacked_height(const LayoutRequest& request);
// The separation chart's height in a comparison scene of this type height
// (PageLayout::type_height_for the picture's height).
int comparison_chart_height(int type_height);
// The legend's rows in a comparison scene of `runs` runs: one per run, the
// key of the line drawn after a run's pixel-true time, and the trail's caption.
int comparison_legend_rows(int runs);
int comparison_runs(int legend_rows);  // the inverse
// The height of one legend row, and of the caption's line, at this type height.
int legend_row_height(int type_height);
// What a frame asks of a picture of this size.
LayoutRequest layout_request(const Frame& frame, int width, int height, int reserved_left = 0);

// The 3D view's vertical field of view, and the camera's distance from the
// sphere's centre for a view of this aspect: the unit sphere (with its pole
// labels) fits the narrower side at the nominal distance of 3.4 radii.
constexpr float kFovDegrees = 30.0f;
float camera_distance_for(double distance_setting, float aspect);

// The overlay's font size at this type height (a picture's height, or
// PageLayout::type_height), and how many of its lines fit a picture of this
// height (below 480 rows, gallery tiles, only the time and the method).
float overlay_font_px(int type_height);
// The type height that gives the overlay's font this size (the inverse of
// overlay_font_px above 13 px): what a figure at a printed size asks for.
int type_height_for_font(float font_px);
// What line widths, marks and paddings are multiplied by at this type
// height: 1 up to 720 rows, then in proportion (3 at 2160).
float ui_scale(int type_height);
int overlay_lines_shown(int lines, int height);
// Whether a picture of this height shows the drift table as one line (the
// largest drift, named), not a row per integral with its key: below 480
// rows, where the overlay floats over the 3D view and must leave it room.
bool overlay_drifts_in_one_line(int height);

}  // namespace epviz::scene
