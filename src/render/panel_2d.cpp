#include "render/panel_2d.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

namespace epviz::render {
namespace {

double nice_step(double span, int target_count) {
  const double raw = span / std::max(target_count, 1);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double fraction = raw / magnitude;
  const double nice = fraction < 1.5 ? 1.0 : fraction < 3.0 ? 2.0 : fraction < 7.0 ? 5.0 : 10.0;
  return nice * magnitude;
}

// Liang-Barsky: clips segment a->b to the box; returns false if nothing is left,
// else the parameters t0 <= t1 of the visible part.
bool clip_segment(const glm::dvec2& a, const glm::dvec2& b, const DataRange& box, double& t0,
                  double& t1) {
  t0 = 0.0;
  t1 = 1.0;
  const glm::dvec2 d = b - a;
  const double p[4] = {-d.x, d.x, -d.y, d.y};
  const double q[4] = {a.x - box.x_min, box.x_max - a.x, a.y - box.y_min, box.y_max - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0.0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace

std::vector<double> nice_ticks(double lo, double hi, int target_count) {
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return {};
  const double step = nice_step(hi - lo, target_count);
  std::vector<double> ticks;
  for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + step * 1e-9; k += 1.0) {
    const double value = k * step;
    ticks.push_back(std::abs(value) < step * 1e-9 ? 0.0 : value);
  }
  return ticks;
}

std::string format_tick(double value, double spacing) {
  const int decimals =
      spacing > 0 ? std::clamp(static_cast<int>(std::ceil(-std::log10(spacing) - 1e-9)), 0, 9) : 0;
  if (std::abs(value) < spacing * 1e-9) value = 0.0;
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

Panel2D::Panel2D(const Viewport& plot_area, const DataRange& range, bool equal_aspect)
    : area_(plot_area), range_(range) {
  if (area_.width <= 0 || area_.height <= 0)
    throw std::invalid_argument("panel plot area must be non-empty");
  if (!(range_.x_max > range_.x_min) || !(range_.y_max > range_.y_min))
    throw std::invalid_argument("panel data range must have max > min on both axes");
  if (equal_aspect) {
    const double x_per_pixel = (range_.x_max - range_.x_min) / area_.width;
    const double y_per_pixel = (range_.y_max - range_.y_min) / area_.height;
    const double per_pixel = std::max(x_per_pixel, y_per_pixel);
    const double cx = 0.5 * (range_.x_min + range_.x_max), cy = 0.5 * (range_.y_min + range_.y_max);
    range_ = {cx - 0.5 * per_pixel * area_.width, cx + 0.5 * per_pixel * area_.width,
              cy - 0.5 * per_pixel * area_.height, cy + 0.5 * per_pixel * area_.height};
  }
}

glm::vec2 Panel2D::to_pixel(const glm::dvec2& data) const {
  const double u = (data.x - range_.x_min) / (range_.x_max - range_.x_min);
  const double v = (data.y - range_.y_min) / (range_.y_max - range_.y_min);
  return {static_cast<float>(area_.x + u * area_.width),
          static_cast<float>(area_.y + (1.0 - v) * area_.height)};
}

bool Panel2D::contains(const glm::dvec2& data) const {
  return data.x >= range_.x_min && data.x <= range_.x_max && data.y >= range_.y_min &&
         data.y <= range_.y_max;
}

void Panel2D::draw_axes(DrawList& list, const PanelStyle& style) const {
  const glm::vec2 top_left(static_cast<float>(area_.x), static_cast<float>(area_.y));
  const glm::vec2 bottom_right(static_cast<float>(area_.x + area_.width),
                               static_cast<float>(area_.y + area_.height));
  list.add_rect(top_left, bottom_right, style.background);

  auto tick_count = [&](int pixels) {
    return std::max(1,
                    std::min(style.tick_count,
                             static_cast<int>(pixels / std::max(style.min_tick_spacing_px, 1.0f))));
  };
  const auto x_ticks = nice_ticks(range_.x_min, range_.x_max, tick_count(area_.width));
  const auto y_ticks = nice_ticks(range_.y_min, range_.y_max, tick_count(area_.height));
  const double x_step = x_ticks.size() > 1 ? x_ticks[1] - x_ticks[0] : 1.0;
  const double y_step = y_ticks.size() > 1 ? y_ticks[1] - y_ticks[0] : 1.0;
  auto line = [&](glm::vec2 a, glm::vec2 b, const glm::vec4& colour, float width) {
    list.add_line(glm::vec3(a, 0.0f), glm::vec3(b, 0.0f), colour, width);
  };

  if (style.grid_lines) {
    for (double x : x_ticks) {
      const float px = to_pixel({x, 0.0}).x;
      line({px, top_left.y}, {px, bottom_right.y}, style.grid, style.grid_width);
    }
    for (double y : y_ticks) {
      const float py = to_pixel({0.0, y}).y;
      line({top_left.x, py}, {bottom_right.x, py}, style.grid, style.grid_width);
    }
  }
  if (range_.x_min < 0.0 && range_.x_max > 0.0) {
    const float px = to_pixel({0.0, 0.0}).x;
    line({px, top_left.y}, {px, bottom_right.y}, style.axis, style.axis_width);
  }
  if (range_.y_min < 0.0 && range_.y_max > 0.0) {
    const float py = to_pixel({0.0, 0.0}).y;
    line({top_left.x, py}, {bottom_right.x, py}, style.axis, style.axis_width);
  }
  // The frame sits half a line outside the area so it never covers data.
  const float h = 0.5f * style.frame_width;
  const glm::vec3 frame[] = {{top_left.x - h, top_left.y - h, 0},
                             {bottom_right.x + h, top_left.y - h, 0},
                             {bottom_right.x + h, bottom_right.y + h, 0},
                             {top_left.x - h, bottom_right.y + h, 0}};
  list.add_polyline(frame, style.frame, style.frame_width, true);

  for (double x : x_ticks) {
    const float px = to_pixel({x, 0.0}).x;
    line({px, bottom_right.y + h}, {px, bottom_right.y + h + style.tick_length}, style.frame,
         style.frame_width);
    if (style.tick_labels)
      list.add_text({glm::vec3(px, bottom_right.y + h + style.tick_length + 2.0f, 0.0f),
                     format_tick(x, x_step), style.text, TextAnchor::top});
  }
  for (double y : y_ticks) {
    const float py = to_pixel({0.0, y}).y;
    line({top_left.x - h - style.tick_length, py}, {top_left.x - h, py}, style.frame,
         style.frame_width);
    if (style.tick_labels)
      list.add_text({glm::vec3(top_left.x - h - style.tick_length - 3.0f, py, 0.0f),
                     format_tick(y, y_step), style.text, TextAnchor::right});
  }
}

void Panel2D::draw_polyline(DrawList& list, std::span<const glm::dvec2> points,
                            std::span<const glm::vec4> colours, float width_px) const {
  if (points.size() < 2 || colours.empty()) return;
  auto colour_at = [&](std::size_t i) {
    return colours.size() == 1 ? colours[0] : colours[std::min(i, colours.size() - 1)];
  };
  std::vector<LineVertex> run;  // the visible piece being built
  auto flush = [&] {
    if (run.size() >= 2) list.add_polyline(run, width_px);
    run.clear();
  };
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    double t0 = 0, t1 = 1;
    if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y) ||
        !std::isfinite(points[i + 1].x) || !std::isfinite(points[i + 1].y) ||
        !clip_segment(points[i], points[i + 1], range_, t0, t1)) {
      flush();
      continue;
    }
    const glm::dvec2 a = points[i] + t0 * (points[i + 1] - points[i]);
    const glm::dvec2 b = points[i] + t1 * (points[i + 1] - points[i]);
    const glm::vec4 ca = glm::mix(colour_at(i), colour_at(i + 1), static_cast<float>(t0));
    const glm::vec4 cb = glm::mix(colour_at(i), colour_at(i + 1), static_cast<float>(t1));
    if (run.empty() || t0 > 0.0) {
      flush();
      run.push_back({glm::vec3(to_pixel(a), 0.0f), ca});
    }
    run.push_back({glm::vec3(to_pixel(b), 0.0f), cb});
    if (t1 < 1.0) flush();  // the curve leaves the area here
  }
  flush();
}

void Panel2D::draw_circle(DrawList& list, const glm::dvec2& centre, double radius,
                          const glm::vec4& colour, float width_px, int segments) const {
  std::vector<glm::dvec2> points;
  points.reserve(static_cast<std::size_t>(segments) + 1);
  for (int i = 0; i <= segments; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / segments;
    points.push_back(centre + radius * glm::dvec2(std::cos(angle), std::sin(angle)));
  }
  const glm::vec4 colours[] = {colour};
  draw_polyline(list, points, colours, width_px);
}

void Panel2D::draw_marker(DrawList& list, const glm::dvec2& at, Marker style) const {
  style.position = glm::vec3(to_pixel(at), 0.0f);
  list.add_marker(style);
}

void Panel2D::draw_text(DrawList& list, const glm::dvec2& at, TextLabel label) const {
  label.position = glm::vec3(to_pixel(at), 0.0f);
  list.add_text(std::move(label));
}

}  // namespace epviz::render
