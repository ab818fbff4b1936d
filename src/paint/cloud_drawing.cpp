#include "paint/cloud_drawing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace epviz::paint {
namespace {

// The spread chart's vertical range: log10 of the fraction of the sphere,
// from well under one histogram cell (1/1152) to the whole sphere.
constexpr double kLogSpreadMin = -3.5, kLogSpreadMax = 0.0;

double log_spread(float fraction) {
  return std::clamp(std::log10(std::max(double(fraction), 1e-12)), kLogSpreadMin, kLogSpreadMax);
}

}  // namespace

glm::vec4 cloud_colour(const scene::Frame& f) {
  const auto& c = f.colours.marker;
  return {c[0], c[1], c[2], 0.5f};
}

void draw_cloud_sphere(render::DrawList& list, const scene::CloudFrame& cloud,
                       const glm::vec4& colour, float px) {
  // Small and without outline: ten thousand points must not hide each other
  // more than their density says.
  render::Marker m;
  m.fill = colour;
  m.outline = colour;
  m.radius_px = 1.1f * px;
  m.outline_px = 0.0f;
  for (const auto& p : cloud.sphere) {
    m.position = {p.x(), p.y(), p.z()};
    list.add_marker(m);
  }
}

void draw_cloud_plane(render::DrawList& flat, const render::Panel2D& plot,
                      const scene::CloudFrame& cloud, const glm::vec4& colour, float px) {
  render::Marker m;
  m.fill = colour;
  m.outline = colour;
  m.radius_px = 0.9f * px;
  m.outline_px = 0.0f;
  for (const auto& p : cloud.plane) plot.draw_marker(flat, {p.x(), p.y()}, m);
}

void draw_cloud_spread(render::DrawList& flat, const render::Viewport& view,
                       const scene::CloudFrame& cloud, const glm::vec4& colour,
                       const scene::Theme& ink, float px) {
  if (cloud.spread.empty() || cloud.t_end <= 0.0) return;
  const int w = int(std::min(150.0f * px, 0.4f * float(view.width)));
  const int h = int(std::min(45.0f * px, 0.25f * float(view.height)));
  const int margin = int(12.0f * px);
  // Top left: the colour bar of the trail's time takes the bottom left.
  const render::Viewport area{view.x + margin, view.y + margin + int(18.0f * px), w, h};
  const render::Panel2D plot(area, {0.0, cloud.t_end, kLogSpreadMin, kLogSpreadMax}, false);
  auto rgba = [](const scene::Rgba& c) { return glm::vec4(c[0], c[1], c[2], c[3]); };
  render::PanelStyle s;
  s.background = rgba(ink.panel_background);
  s.frame = rgba(ink.panel_frame);
  s.axis = rgba(ink.panel_axis);
  s.text = rgba(ink.panel_text);
  s.tick_labels = false;
  s.grid_lines = false;
  s.tick_length = 0.0f;
  s.frame_width = s.axis_width = 1.0f * px;
  plot.draw_axes(flat, s);
  std::vector<glm::dvec2> curve;
  curve.reserve(cloud.spread.size());
  for (const auto& p : cloud.spread) curve.emplace_back(p.x(), log_spread(p.y()));
  const glm::vec4 line{colour.r, colour.g, colour.b, 1.0f};
  if (curve.size() >= 2) plot.draw_polyline(flat, curve, std::span(&line, 1), 1.5f * px);
  char text[120];
  std::snprintf(text, sizeof text, "cloud of %d: covers %.2g%% of the sphere", cloud.members,
                100.0 * double(cloud.spread.back().y()));
  plot.draw_text(flat, {0.0, kLogSpreadMax},
                 {{}, text, s.text, render::TextAnchor::bottom_left, {0.0f, -4.0f * px}});
}

}  // namespace epviz::paint
