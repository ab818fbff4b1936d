#pragma once
// The axes of the small charts inside a frame (the comparison's separation
// chart, the cloud's spread): a log10 axis ticked at whole decades, a time
// axis ticked at nice values, each label measured so that the chart fits
// the rectangle it is given and no two labels overlap.
#include <functional>
#include <string>
#include <vector>

#include <glm/vec2.hpp>

#include "render/draw_list.hpp"
#include "render/panel_2d.hpp"
#include "scene/theme.hpp"

namespace epviz::paint {

// A text's width and height in pixels, as the picture's font sets it.
using MeasureText = std::function<glm::vec2(const std::string&)>;

struct AxisTick {
  double at = 0.0;    // plotted units (log10 on a log axis)
  std::string label;  // empty: a tick without a label
};

// A tick at every whole decade of [lo, hi] (log10 units); labelled every
// decade when their labels fit `px_per_decade`, else every 2nd, 3rd, 5th...
// decade, always including 0 when it is in range. `name` labels a decade.
std::vector<AxisTick> decade_ticks(int lo, int hi, float px_per_decade, float label_height,
                                   const std::function<std::string(int)>& name);

// Ticks of a time axis [0, t_end] about `width_px` wide, their labels in
// print, as many as fit with a label's width of room between them.
std::vector<AxisTick> time_ticks(double t_end, float width_px, const MeasureText& measure);

// An axis-aligned box in image pixels.
struct TextBox {
  glm::vec2 min{0.0f}, max{0.0f};
  bool intersects(const TextBox& o) const {
    return min.x < o.max.x && o.min.x < max.x && min.y < o.max.y && o.min.y < max.y;
  }
};
// Where `label` (in image pixels, its offset applied) is drawn, `size` big.
TextBox text_box(const render::TextLabel& label, glm::vec2 size);

struct SmallChartStyle {
  glm::vec4 text{1.0f}, grid{1.0f, 1.0f, 1.0f, 0.08f}, tick{1.0f};
  float px = 1.0f;  // the picture's line-width scale
};

// The plot's frame, in the theme's panel colours on `background` (no axes,
// grid or ticks of its own: draw_small_chart_ticks adds those), and the
// style those ticks take from the theme.
SmallChartStyle draw_small_chart_frame(render::DrawList& list, const render::Panel2D& plot,
                                       const glm::vec4& background, const scene::Theme& ink,
                                       float px);

// The room the y labels need left of the plot: the widest label, a tick
// and a gap.
float y_label_room(const std::vector<AxisTick>& y, const MeasureText& measure, float px);

// Ticks, grid lines and labels of `x` (under the plot) and `y` (left of
// it) on `plot`. A y label that would overlap an x label (at the bottom
// left corner) or a box of `keep_out` (a title) is left out, its tick kept.
void draw_small_chart_ticks(render::DrawList& list, const render::Panel2D& plot,
                            const std::vector<AxisTick>& x, const std::vector<AxisTick>& y,
                            const SmallChartStyle& style, const MeasureText& measure,
                            std::vector<TextBox> keep_out = {});

}  // namespace epviz::paint
