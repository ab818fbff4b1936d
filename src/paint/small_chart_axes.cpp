#include "paint/small_chart_axes.hpp"

#include <algorithm>
#include <cmath>

#include "paint/figure_common.hpp"
#include "paint/painter_common.hpp"
#include "render/gui_overlay.hpp"

namespace epviz::paint {

std::vector<AxisTick> decade_ticks(int lo, int hi, float px_per_decade, float label_height,
                                   const std::function<std::string(int)>& name) {
  // A label's height and a little air between neighbours.
  const float needed = 1.15f * label_height;
  int step = 1;
  for (int s : {1, 2, 3, 5, 10, 20}) {
    step = s;
    if (float(s) * px_per_decade >= needed) break;
  }
  std::vector<AxisTick> ticks;
  for (int e = lo; e <= hi; ++e)
    ticks.push_back({double(e), e % step == 0 ? name(e) : std::string()});
  return ticks;
}

std::vector<AxisTick> time_ticks(double t_end, float width_px, const MeasureText& measure) {
  if (!(t_end > 0.0) || width_px <= 0.0f) return {{0.0, "0"}};
  // The widest label is about as wide as t_end's own: leave that much again
  // between two labels.
  const float label_w = std::max(measure(render::format_tick(t_end, t_end)).x, 1.0f);
  int count = std::clamp(int(width_px / (2.0f * label_w + 4.0f)), 1, 8);
  for (;; --count) {
    const auto values = render::nice_ticks(0.0, t_end, count + 1);
    const double spacing = values.size() > 1 ? values[1] - values[0] : t_end;
    std::vector<AxisTick> ticks;
    float widest = 0.0f;
    for (double v : values) {
      ticks.push_back({v, print_minus(render::format_tick(v, spacing))});
      widest = std::max(widest, measure(ticks.back().label).x);
    }
    const float gap = float(spacing / t_end) * width_px;
    if (count <= 1 || gap >= widest + 4.0f) return ticks;
  }
}

TextBox text_box(const render::TextLabel& label, glm::vec2 size) {
  const glm::vec2 at = glm::vec2(label.position) + label.offset_px;
  const glm::vec2 top_left = render::anchored_top_left(at, size, label.anchor);
  return {top_left, top_left + size};
}

SmallChartStyle draw_small_chart_frame(render::DrawList& list, const render::Panel2D& plot,
                                       const glm::vec4& background, const scene::Theme& ink,
                                       float px) {
  render::PanelStyle frame;
  frame.background = background;
  frame.frame = to_glm(ink.panel_frame);
  frame.axis = {0, 0, 0, 0};
  frame.tick_labels = false;
  frame.grid_lines = false;
  frame.tick_length = 0.0f;
  frame.frame_width = 1.0f * px;
  draw_axes_in_print(plot, list, frame);
  SmallChartStyle ticks;
  ticks.text = to_glm(ink.panel_text);
  ticks.grid = to_glm(ink.panel_grid);
  ticks.tick = to_glm(ink.panel_frame);
  ticks.px = px;
  return ticks;
}

float y_label_room(const std::vector<AxisTick>& y, const MeasureText& measure, float px) {
  float widest = 0.0f;
  for (const auto& t : y)
    if (!t.label.empty()) widest = std::max(widest, measure(t.label).x);
  return widest + 6.0f * px;
}

void draw_small_chart_ticks(render::DrawList& list, const render::Panel2D& plot,
                            const std::vector<AxisTick>& x, const std::vector<AxisTick>& y,
                            const SmallChartStyle& style, const MeasureText& measure,
                            std::vector<TextBox> keep_out) {
  const auto& area = plot.plot_area();
  const float left = float(area.x), right = float(area.x + area.width);
  const float top = float(area.y), bottom = float(area.y + area.height);
  const float tick = 3.0f * style.px, width = 1.0f * style.px;
  auto line = [&](glm::vec2 a, glm::vec2 b, const glm::vec4& colour) {
    list.add_line(glm::vec3(a, 0.0f), glm::vec3(b, 0.0f), colour, width);
  };
  for (const auto& t : x) {
    const float at = plot.to_pixel({t.at, plot.range().y_min}).x;
    if (at > left + 0.5f && at < right - 0.5f) line({at, top}, {at, bottom}, style.grid);
    line({at, bottom}, {at, bottom + tick}, style.tick);
    if (t.label.empty()) continue;
    render::TextLabel l{
        {at, bottom + tick + 1.0f * style.px, 0.0f}, t.label, style.text, render::TextAnchor::top};
    keep_out.push_back(text_box(l, measure(l.text)));
    list.add_text(std::move(l));
  }
  for (const auto& t : y) {
    const float at = plot.to_pixel({plot.range().x_min, t.at}).y;
    if (!t.label.empty() && at > top + 0.5f && at < bottom - 0.5f)
      line({left, at}, {right, at}, style.grid);
    line({left - tick, at}, {left, at}, style.tick);
    if (t.label.empty()) continue;
    render::TextLabel l{
        {left - tick - 2.0f * style.px, at, 0.0f}, t.label, style.text, render::TextAnchor::right};
    const TextBox box = text_box(l, measure(l.text));
    if (std::any_of(keep_out.begin(), keep_out.end(),
                    [&](const TextBox& b) { return b.intersects(box); }))
      continue;
    list.add_text(std::move(l));
  }
}

}  // namespace epviz::paint
