#pragma once
// A 2D plot panel: a rectangle of the image with its own data-to-pixel mapping
// (optionally equal aspect, as a geometric plane needs), that writes axes,
// ticks, tick labels, circles, polylines and markers into a DrawList in image
// pixels. Curves are clipped to the plot rectangle here, on the CPU; callers
// who must not clip silently ask contains() and mark the exits themselves.
#include <span>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "render/camera.hpp"
#include "render/draw_list.hpp"

namespace epviz::render {

struct DataRange {
  double x_min = -1.0;
  double x_max = 1.0;
  double y_min = -1.0;
  double y_max = 1.0;
};

// About `target_count` "nice" values (1, 2 or 5 times a power of ten apart) inside [lo, hi].
std::vector<double> nice_ticks(double lo, double hi, int target_count = 5);
// A tick label with no more decimals than the tick spacing needs ("-0" printed as "0").
std::string format_tick(double value, double spacing);

struct PanelStyle {
  glm::vec4 background{0.10f, 0.11f, 0.13f, 1.0f};
  glm::vec4 frame{0.45f, 0.47f, 0.52f, 1.0f};
  glm::vec4 grid{1.0f, 1.0f, 1.0f, 0.07f};
  glm::vec4 axis{0.75f, 0.77f, 0.82f, 0.8f};  // the lines x = 0 and y = 0
  glm::vec4 text{0.80f, 0.82f, 0.86f, 1.0f};
  float frame_width = 1.0f;
  float axis_width = 1.25f;
  float grid_width = 1.0f;
  float tick_length = 5.0f;
  int tick_count = 5;                 // at most this many ticks per axis...
  float min_tick_spacing_px = 36.0f;  // ...and no closer than this, so labels do not collide
  bool grid_lines = true;
  bool tick_labels = true;
};

class Panel2D {
 public:
  // `plot_area`: where data is drawn (leave margins outside it for tick labels).
  // With `equal_aspect` the data range is widened so one unit spans the same
  // number of pixels on both axes (circles stay round), centred on the request.
  Panel2D(const Viewport& plot_area, const DataRange& range, bool equal_aspect = true);

  const Viewport& plot_area() const { return area_; }
  const DataRange& range() const { return range_; }
  // Data -> image pixels (y down).
  glm::vec2 to_pixel(const glm::dvec2& data) const;
  bool contains(const glm::dvec2& data) const;

  // Background, grid, axis lines through 0, frame, ticks and tick labels.
  void draw_axes(DrawList& list, const PanelStyle& style = {}) const;
  // A polyline in data coordinates, one colour per point (or one for all if
  // `colours` has a single entry); clipped to the plot area.
  void draw_polyline(DrawList& list, std::span<const glm::dvec2> points,
                     std::span<const glm::vec4> colours, float width_px) const;
  void draw_circle(DrawList& list, const glm::dvec2& centre, double radius, const glm::vec4& colour,
                   float width_px, int segments = 256) const;
  // A marker at a data point (drawn even outside the area; check contains()).
  void draw_marker(DrawList& list, const glm::dvec2& at, Marker style) const;
  // A text label at a data point.
  void draw_text(DrawList& list, const glm::dvec2& at, TextLabel label) const;

 private:
  Viewport area_;
  DataRange range_;
};

}  // namespace epviz::render
