#include "scene/layout.hpp"

#include <algorithm>
#include <cmath>

namespace epviz::scene {
namespace {

// Height reserved for the overlay window: the title, the lines a picture of
// this height shows, the drift table's heading, its rows and its key. Fixed
// (kOverlayReserved), not this frame's: the plot must stay put from job to
// job so that the tiles of a gallery line up.
int overlay_height(int height, int type_height, int runs) {
  // A comparison of more runs than kOverlayReserved has drift rows gets room
  // for each run's row.
  const OverlayShape o{kOverlayReserved.lines, std::max(kOverlayReserved.drifts, runs)};
  const int rows = 1 + overlay_lines_shown(o.lines, height) +
                   (overlay_drifts_in_one_line(height) ? 1 : 2 + o.drifts);
  return int(std::ceil(overlay_font_px(type_height) * 1.36f * float(rows) +
                       18.0f * ui_scale(type_height)));
}

int overlay_height_for(const LayoutRequest& q) {
  return overlay_height(q.height, q.page.type_height_for(q.height),
                        q.legend_rows > 0 ? comparison_runs(q.legend_rows) : 0);
}

// The margins around a plot of the panel column: room for its title above,
// its tick labels and caption (and a comparison's chart) below.
struct PlotMargins {
  int top = 0, bottom = 0, left = 0, right = 0;
};
PlotMargins plot_margins(const LayoutRequest& q, int slot_width) {
  const int th = q.page.type_height_for(q.height);
  return {std::max(22, th / 14),
          std::max(int(std::ceil(overlay_font_px(th) * 2.9f)), th / 9) + q.chart_height,
          std::max(30, slot_width / 8), std::max(10, slot_width / 20)};
}

int column_slots(const LayoutRequest& q) {
  return (q.layers.riccati ? 1 : 0) + (q.section_panel ? 1 : 0);
}

// The column's plots side by side, each in a slot of its own (the Riccati
// plane, then the section), squares of side `side` placed from `top`.
void place_plots(const LayoutRequest& q, FrameLayout& l, int top, int side, const PlotMargins& m) {
  const auto& c = *l.panel_column;
  const int slots = column_slots(q);
  const int slot_width = c.width / slots;
  auto plot_in_slot = [&](int slot) {
    const int x0 = c.x + slot * slot_width;
    return Rect{x0 + m.left + (slot_width - m.left - m.right - side) / 2, top, side, side};
  };
  if (q.layers.riccati) {
    l.plot_area = plot_in_slot(0);
    const int x = l.plot_area->x;
    if (q.chart_height > 0)  // below the plot's tick labels
      l.chart_area = Rect{x, top + side + m.bottom - q.chart_height, side, q.chart_height * 4 / 5};
    l.plane_px_per_unit = double(side) / (2.0 * double(q.plane_extent));
  }
  if (q.section_panel) l.section_area = plot_in_slot(slots - 1);
}

// The perspective scale at the sphere's centre in the 3D view `view`: half
// the view's height spans tan(fov / 2) at the camera's distance.
double sphere_px_per_unit(const LayoutRequest& q, const Rect& view) {
  const float aspect = view.height > 0 ? float(view.width) / float(view.height) : 1.0f;
  const double half_tan = std::tan(double(kFovDegrees) * M_PI / 360.0);
  return 0.5 * double(view.height) /
         (double(camera_distance_for(q.camera_distance, aspect)) * half_tan);
}

// The height of a comparison's legend: its rows and a margin.
int legend_strip_height(const LayoutRequest& q) {
  const int th = q.page.type_height_for(q.height);
  return q.legend_rows * legend_row_height(th) + int(std::ceil(8.0f * ui_scale(th)));
}

// A stacked page: the caption, the 3D view across the width (4:3), its
// legend, the overlay's band, then the panels' column, each part as tall as
// it needs, whatever the picture's height (stacked_height is the sum).
FrameLayout layout_stacked(const LayoutRequest& q, int width) {
  const int th = q.page.type_height_for(q.height);
  FrameLayout l;
  int y = 0;
  if (q.caption) {
    l.caption_area = Rect{0, 0, width, legend_row_height(th)};
    y = l.caption_area->bottom();
  }
  const bool three_d = q.layers.body || q.layers.sphere;
  if (three_d) {
    l.view_3d = Rect{0, y, width, width * 3 / 4};
    y = l.view_3d->bottom();
    if (q.legend_rows > 0) {
      l.legend_area = Rect{0, y, width, legend_strip_height(q)};
      y = l.legend_area->bottom();
    }
  }
  if (q.layers.overlay) {
    l.overlay_area = Rect{0, y, width, overlay_height_for(q)};
    l.overlay_in_column = true;
    y = l.overlay_area->bottom();
  }
  const int slots = column_slots(q);
  if (slots > 0) {
    const int slot_width = width / slots;
    PlotMargins m = plot_margins(q, slot_width);
    // The tick labels left of a plot ("−2") take about three characters of
    // the type asked, however narrow the slot.
    m.left = std::max(m.left, int(std::ceil(overlay_font_px(th) * 2.6f)));
    // One plot alone is kept to two thirds of the width: a page's column
    // gains nothing from a plane as wide as the sphere's view.
    const int side = std::max(16, std::min(slot_width - m.left - m.right, width * 2 / 3));
    l.panel_column = Rect{0, y, width, m.top + side + m.bottom};
    place_plots(q, l, y + m.top, side, m);
    if (!three_d && q.legend_rows > 0) {
      const int bottom = y + m.top + side + m.bottom;
      l.legend_area = Rect{0, bottom, width, legend_strip_height(q)};
    }
  }
  if (l.view_3d) l.sphere_px_per_unit = sphere_px_per_unit(q, *l.view_3d);
  return l;
}

int bottom_of(const FrameLayout& l) {
  int bottom = 0;
  for (const auto* r : {&l.view_3d, &l.panel_column, &l.plot_area, &l.chart_area, &l.legend_area,
                        &l.caption_area, &l.section_area, &l.overlay_area})
    if (*r) bottom = std::max(bottom, (*r)->bottom());
  return bottom;
}

FrameLayout layout_in_width(const LayoutRequest& q, int width) {
  if (q.page.stacked) return layout_stacked(q, width);
  const int height = q.height;
  const int th = q.page.type_height_for(height);
  FrameLayout l;
  // A caption takes a line across the top; everything else goes below it.
  const int top = q.caption ? legend_row_height(th) : 0;
  if (q.caption) l.caption_area = Rect{0, 0, width, top};
  const int h = height - top;
  const bool three_d = q.layers.body || q.layers.sphere;
  const bool column = q.layers.riccati || q.section_panel;
  // The 3D view takes the left 60 % when the panel is shown, half the width
  // when the column holds a section panel beside it.
  if (three_d && column) {
    const int w3 = q.section_panel ? width / 2 : width * 3 / 5;
    l.view_3d = Rect{0, top, w3, h};
    l.panel_column = Rect{w3, top, width - w3, h};
  } else if (three_d) {
    l.view_3d = Rect{0, top, width, h};
  } else if (column) {
    l.panel_column = Rect{0, top, width, h};
  }
  // The legend of a comparison: a strip under the 3D view (under the panel
  // without one), so that it never covers the sphere or a mark.
  if (q.legend_rows > 0 && (l.view_3d || l.panel_column)) {
    Rect& above = l.view_3d ? *l.view_3d : *l.panel_column;
    const int strip = std::min(above.height / 2, legend_strip_height(q));
    above.height -= strip;
    l.legend_area = Rect{above.x, above.bottom(), above.width, strip};
  }
  if (l.panel_column) {
    const auto& c = *l.panel_column;
    // The column's plots side by side, each in a slot of its own: the
    // Riccati plane, then the section.
    const int slots = column_slots(q);
    const int slot_width = c.width / slots;
    const PlotMargins m = plot_margins(q, slot_width);
    auto side_for = [&](int margin_top) {
      return std::min(slot_width - m.left - m.right, c.height - margin_top - m.bottom);
    };
    // The overlay takes the top of the panel's column when the plot keeps at
    // least 35 % of the height there (a quarter beside a section panel), so
    // that it does not cover the sphere; otherwise (small pictures) it floats
    // over the 3D view. A place the job asks for (OverlayPlace) decides instead.
    const int overlay_px = l.view_3d && q.layers.overlay ? overlay_height_for(q) : 0;
    const int least_side = height * (slots > 1 ? 25 : 35) / 100;
    // Small pictures (their drift table in one line) float it: their column
    // is too narrow for its lines.
    const OverlayPlace place = q.page.overlay;
    l.overlay_in_column = overlay_px > 0 && (place == OverlayPlace::beside ||
                                             (place == OverlayPlace::automatic &&
                                              !overlay_drifts_in_one_line(height) &&
                                              side_for(m.top + overlay_px) >= least_side));
    const int margin_top = m.top + (l.overlay_in_column ? overlay_px : 0);
    const int side = std::max(16, side_for(margin_top));
    const int y = c.y + margin_top + (c.height - margin_top - m.bottom - side) / 2;
    place_plots(q, l, y, side, m);
  }
  if (l.view_3d) l.sphere_px_per_unit = sphere_px_per_unit(q, *l.view_3d);
  return l;
}

}  // namespace

OverlayShape overlay_shape(const OverlayText& o) {
  return {int(o.lines.size()), int(o.drifts.size())};
}

// Text grows with the picture (a 4K still reads like the 720p one scaled up);
// below 13 px it would not read at all.
float overlay_font_px(int type_height) { return std::max(float(type_height) / 48.0f, 13.0f); }

int type_height_for_font(float font_px) { return int(std::lround(font_px * 48.0f)); }

float ui_scale(int type_height) { return std::max(1.0f, float(type_height) / 720.0f); }

int overlay_lines_shown(int lines, int height) { return std::min(lines, height < 480 ? 2 : lines); }

bool overlay_drifts_in_one_line(int height) { return height < 480; }

float camera_distance_for(double distance_setting, float aspect) {
  // Degrees to radians as glm::radians does, so that the painter's camera is unchanged to the bit.
  const float half =
      std::tan(kFovDegrees * 0.01745329251994329577f / 2.0f) * std::min(1.0f, aspect);
  return float(distance_setting) * (1.22f / half) / 3.4f;
}

int comparison_chart_height(int type_height) { return std::max(60, type_height / 5); }

int comparison_legend_rows(int runs) { return runs + 2; }

int comparison_runs(int legend_rows) { return legend_rows - 2; }

int legend_row_height(int type_height) {
  return int(std::ceil(overlay_font_px(type_height) * 1.45f));
}

LayoutRequest layout_request(const Frame& f, int width, int height, int reserved_left) {
  return {width,
          height,
          f.layers,
          overlay_shape(f.overlay),
          f.camera.distance,
          f.plane_extent,
          reserved_left,
          f.comparison ? comparison_chart_height(f.page.type_height_for(height)) : 0,
          f.comparison ? comparison_legend_rows(int(f.comparison->labels.size())) : 0,
          !f.caption.empty(),
          f.section.has_value(),
          f.page};
}

int stacked_height(const LayoutRequest& request) {
  LayoutRequest q = request;
  q.page.stacked = true;
  // Tall enough that the overlay shows all its lines; a stacked page's parts
  // take what they need whatever the height.
  q.height = std::max(q.height, 480);
  return std::max(1, bottom_of(layout_in_width(q, q.width)));
}

FrameLayout frame_layout(const LayoutRequest& q) {
  const int reserved_left = std::clamp(q.reserved_left, 0, q.width - 16);
  FrameLayout l = layout_in_width(q, q.width - reserved_left);
  if (reserved_left == 0) return l;
  for (auto* r : {&l.view_3d, &l.panel_column, &l.plot_area, &l.chart_area, &l.legend_area,
                  &l.caption_area, &l.section_area, &l.overlay_area})
    if (*r) (*r)->x += reserved_left;
  return l;
}

}  // namespace epviz::scene
