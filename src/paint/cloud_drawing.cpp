#include "paint/cloud_drawing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/mat4x4.hpp>

#include "paint/figure_common.hpp"

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
                       const glm::vec4& colour, const render::Camera& camera,
                       const render::Viewport& view, float px) {
  if (cloud.sphere.empty() || view.height <= 0) return;
  const glm::mat4& v = camera.view;
  std::vector<render::ColouredVertex> dots;
  dots.reserve(cloud.sphere.size());
  for (const auto& p : cloud.sphere) {
    // A little inside the sphere: the dots write depth, and the trail and
    // the current point on the near side must stay in front of them.
    const glm::vec3 at = 0.997f * glm::vec3(p.x(), p.y(), p.z());
    if (-(v * glm::vec4(at, 1.0f)).z <= 0.0f) continue;  // behind the eye
    dots.push_back({at, colour});
  }
  list.add_dots(dots, 2.0f * px);
}

void draw_cloud_plane(render::DrawList& flat, const render::Panel2D& plot,
                      const scene::CloudFrame& cloud, const glm::vec4& colour, float px) {
  std::vector<render::ColouredVertex> dots;
  dots.reserve(cloud.plane.size());
  for (const auto& p : cloud.plane)
    dots.push_back({glm::vec3(plot.to_pixel({p.x(), p.y()}), 0.0f), colour});
  flat.add_dots(dots, 1.6f * px);
}

void draw_cloud_spread(render::DrawList& flat, const render::Viewport& view,
                       const scene::CloudFrame& cloud, const glm::vec4& colour,
                       const scene::Theme& ink, float px) {
  if (cloud.spread.empty() || cloud.t_end <= 0.0) return;
  const int w = int(std::min(110.0f * px, 0.4f * float(view.width)));
  const int h = int(std::min(35.0f * px, 0.25f * float(view.height)));
  const int margin = int(12.0f * px);
  // Bottom right: the colour bar of the trail's time takes the bottom left,
  // the overlay floating over a small picture's view the top left.
  const render::Viewport area{view.x + view.width - margin - w, view.y + view.height - margin - h,
                              w, h};
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
  draw_axes_in_print(plot, flat, s);
  std::vector<glm::dvec2> curve;
  curve.reserve(cloud.spread.size());
  for (const auto& p : cloud.spread) curve.emplace_back(p.x(), log_spread(p.y()));
  const glm::vec4 line{colour.r, colour.g, colour.b, 1.0f};
  if (curve.size() >= 2) plot.draw_polyline(flat, curve, std::span(&line, 1), 1.5f * px);
  char text[120];
  std::snprintf(text, sizeof text, "cloud of %d: covers %.2g%% of the sphere", cloud.members,
                100.0 * double(cloud.spread.back().y()));
  // Over the chart, ending at its right edge: the text is wider than the
  // chart and would otherwise run out of the view into the panels beside it.
  plot.draw_text(flat, {cloud.t_end, kLogSpreadMax},
                 {{}, text, s.text, render::TextAnchor::bottom_right, {0.0f, -4.0f * px}});
}

}  // namespace epviz::paint
