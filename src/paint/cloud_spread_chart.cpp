#include "paint/cloud_spread_chart.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "paint/cloud_drawing.hpp"
#include "paint/figure_common.hpp"
#include "paint/painter_common.hpp"

namespace epviz::paint {
namespace {

double log_spread(float fraction) {
  return std::clamp(std::log10(std::max(double(fraction), 1e-12)), kLogSpreadMin, kLogSpreadMax);
}

// A decade of the sphere's share as a percentage: "0.1 %", "1 %", "100 %".
std::string percent_of_decade(int exponent) {
  char text[32];
  std::snprintf(text, sizeof text, "%g %%", 100.0 * std::pow(10.0, exponent));
  return text;
}

// The caption: the value now, in at most two lines of `room`, shorter
// where even two lines are too narrow.
std::vector<std::string> caption_for(const scene::CloudFrame& cloud, float room,
                                     const MeasureText& measure) {
  char value[32];
  std::snprintf(value, sizeof value, "%.2g %%", 100.0 * double(cloud.spread.back().y()));
  const std::string candidates[] = {
      "cloud of " + std::to_string(cloud.members) + " covers " + value + " of the sphere",
      "covers " + std::string(value) + " of the sphere"};
  const ChartFont font{measure("100 %").y, [&](const std::string& t) { return measure(t).x; }};
  for (const auto& c : candidates)
    if (auto lines = wrap_text(c, font, room);
        lines.size() <= 2 && std::all_of(lines.begin(), lines.end(), [&](const std::string& l) {
          return measure(l).x <= room;
        }))
      return lines;
  return {"covers " + std::string(value)};
}

}  // namespace

CloudSpreadBoxes draw_cloud_spread_chart(render::DrawList& flat, const render::Viewport& view,
                                         const scene::CloudFrame& cloud, const glm::vec4& colour,
                                         const scene::Theme& ink, float px,
                                         const MeasureText& measure) {
  const double t_axis = std::max(cloud.chart_t_end, cloud.t_end);
  if (cloud.spread.empty() || !(t_axis > 0.0)) return {};
  const float text_h = measure("100 %").y;
  const float pad = 4.0f * px, tick = 3.0f * px, margin = 10.0f * px;
  // Bottom right: the colour bar of the trail's time takes the bottom left,
  // the overlay floating over a small picture's view the top left.
  const float width = std::min(std::max(160.0f * px, 12.0f * text_h), 0.5f * float(view.width));
  const float room = width - 2.0f * pad;
  const auto caption = caption_for(cloud, room, measure);
  const float caption_h = float(caption.size()) * text_h;
  // The caption's lines, a plot with room for a label at each of its
  // decades (3.5 of them, labels 1.15 lines apart), the time labels.
  const float height = std::min(pad + caption_h + pad + 4.6f * text_h + tick + px + text_h + pad,
                                0.45f * float(view.height));
  const glm::vec2 corner{float(view.x + view.width) - margin, float(view.y + view.height) - margin};
  const TextBox panel{corner - glm::vec2(width, height), corner};

  // Every decade of the fixed range, labelled where the labels fit.
  const float plot_top = panel.min.y + pad + caption_h + pad + 0.5f * text_h;
  const float plot_bottom = panel.max.y - pad - text_h - px - tick;
  const float plot_h = std::max(4.0f, plot_bottom - plot_top);
  const auto y_ticks =
      decade_ticks(int(std::ceil(kLogSpreadMin)), int(kLogSpreadMax),
                   plot_h / float(kLogSpreadMax - kLogSpreadMin), text_h, percent_of_decade);
  const float left = pad + y_label_room(y_ticks, measure, px);
  const float right = pad + 0.5f * measure(render::format_tick(t_axis, t_axis)).x;
  const float plot_w = std::max(4.0f, width - left - right);
  const render::Viewport area{int(std::lround(panel.min.x + left)), int(std::lround(plot_top)),
                              int(plot_w), int(plot_h)};
  const render::Panel2D plot(area, {0.0, t_axis, kLogSpreadMin, kLogSpreadMax}, false);

  // The panel, opaque: the cloud's dots under it do not show through the text.
  glm::vec4 background = to_glm(ink.panel_background);
  background.a = 1.0f;
  flat.add_rect(panel.min, panel.max, background);
  const SmallChartStyle ticks = draw_small_chart_frame(flat, plot, background, ink, px);
  std::vector<render::TextLabel> lines;
  TextBox caption_box{panel.min + glm::vec2(pad), panel.min + glm::vec2(pad)};
  for (std::size_t i = 0; i < caption.size(); ++i) {
    lines.push_back({{panel.min.x + pad, panel.min.y + pad + float(i) * text_h, 0.0f},
                     caption[i],
                     ticks.text,
                     render::TextAnchor::top_left});
    const TextBox b = text_box(lines.back(), measure(caption[i]));
    caption_box = {glm::min(caption_box.min, b.min), glm::max(caption_box.max, b.max)};
  }
  draw_small_chart_ticks(flat, plot, time_ticks(t_axis, plot_w, measure), y_ticks, ticks, measure,
                         {caption_box});
  for (auto& l : lines) flat.add_text(std::move(l));

  std::vector<glm::dvec2> curve;
  curve.reserve(cloud.spread.size());
  for (const auto& p : cloud.spread) curve.emplace_back(p.x(), log_spread(p.y()));
  const glm::vec4 line{colour.r, colour.g, colour.b, 1.0f};
  if (curve.size() >= 2) plot.draw_polyline(flat, curve, std::span(&line, 1), 1.5f * px);
  const glm::vec2 top_left{float(area.x), float(area.y)};
  return {
      panel, {top_left, top_left + glm::vec2(float(area.width), float(area.height))}, caption_box};
}

}  // namespace epviz::paint
