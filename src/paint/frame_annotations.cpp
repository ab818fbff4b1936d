// The frame painter's 2D layer over the 3D view: what the marks and colours
// mean, and the labels placed so that none covers another or a mark.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>

#include "paint/comparison_painter.hpp"
#include "paint/frame_painter.hpp"
#include "paint/painter_common.hpp"
#include "paint/trail_colours.hpp"

namespace epviz::paint {
namespace {

using render::DrawList;
using render::TextAnchor;

Box box_of(const render::Viewport& v) {
  return {glm::vec2(v.x, v.y), glm::vec2(v.x + v.width, v.y + v.height)};
}

// A time before now for the colour bar's ticks: short, no trailing zeros.
std::string time_ago(double t) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", t);
  return "−" + std::string(buf);
}

// A small arrow from `from` along `dir` (unit, image pixels) of `length` pixels.
void add_arrow_2d(DrawList& list, glm::vec2 from, glm::vec2 dir, float length, float width,
                  const glm::vec4& colour) {
  const glm::vec2 tip = from + dir * length;
  const glm::vec2 side(-dir.y, dir.x);
  const float head = std::max(4.0f, 3.0f * width);
  list.add_line(glm::vec3(from, 0), glm::vec3(tip - dir * head * 0.8f, 0), colour, width);
  const render::ColouredVertex tri[3] = {
      {glm::vec3(tip, 0), colour},
      {glm::vec3(tip - dir * head + side * head * 0.6f, 0), colour},
      {glm::vec3(tip - dir * head - side * head * 0.6f, 0), colour}};
  list.add_triangles(tri);
}

// The room the current point's marker takes, with a gap, at this line scale.
glm::vec2 current_mark_size(float px) { return glm::vec2(2.0f * (5.0f * px + 3.0f * px)); }

}  // namespace

std::vector<Box> FramePainter::run_mark_boxes(const scene::Frame& f, const render::Camera& camera,
                                              const render::Viewport& view, float px) {
  std::vector<Box> boxes;
  if (!f.layers.sphere) return boxes;
  auto at = [&](const Eigen::Vector3f& point, glm::vec2 size) {
    if (auto p = render::project_to_pixel(camera, view, to_glm(point)))
      boxes.push_back(box_around(glm::vec2(*p), size));
  };
  at(f.current, current_mark_size(px));
  if (f.comparison)
    for (const auto& other : f.comparison->others) at(other.current, ghost_mark_size(px));
  return boxes;
}

void FramePainter::add_placed_labels(DrawList& flat, const std::vector<LabelRequest>& requests,
                                     const std::vector<glm::vec4>& colours,
                                     const std::vector<Box>& obstacles, const Box& bounds) {
  // Earlier labels of the same frame are obstacles too (the 3D view's and the plane's never meet,
  // but a part may place labels in more than one call).
  std::vector<Box> taken = obstacles;
  for (const auto& l : annotations_.labels) taken.push_back(l.box);
  const auto boxes = place_labels(requests, taken, bounds);
  for (std::size_t i = 0; i < requests.size(); ++i) {
    flat.add_text(
        {glm::vec3(boxes[i].min, 0.0f), requests[i].text, colours[i], TextAnchor::top_left});
    annotations_.labels.push_back({requests[i].text, boxes[i], bounds});
  }
}

std::vector<Box> FramePainter::draw_trail_key(DrawList& flat, const scene::Frame& f,
                                              const render::Viewport& view, float px) {
  std::vector<Box> taken;
  if (!f.layers.sphere || f.trail_label.empty()) return taken;
  const scene::Theme& ink = ink_for(f);
  const glm::vec4 text = to_glm(ink.trail_caption);
  const float font = gui().label_font_px();
  const float left = float(view.x) + 8 * px, bottom = float(view.y + view.height) - 6 * px;
  const float room = float(view.width) - 16 * px;

  // In a comparison scene the colours name the runs: the legend's strip
  // (paint/comparison_painter.hpp) says so, and the trail has no time key.
  if (f.comparison) return taken;
  // The caption on the bottom line, as long as the view is wide.
  std::string caption;
  for (const std::string& c :
       {"trail: " + f.trail_label + ", coloured by time", "trail: " + f.trail_label, f.trail_label})
    if (gui().text_size(c).x <= room) {
      caption = c;
      break;
    }
  float y = bottom;
  if (!caption.empty()) {
    const glm::vec2 size = gui().text_size(caption);
    flat.add_text({{left, y, 0}, caption, text, TextAnchor::bottom_left});
    taken.push_back({{left, y - size.y}, {left + size.x, y}});
    y -= size.y + 2 * px;
  }

  // The colour bar above it: the trail's colours from its oldest point (left)
  // to now (right), with the time before now under its ends and middle.
  const std::string old_end = f.trail_time > 0.0 ? time_ago(f.trail_time) : "old";
  const std::string middle = f.trail_time > 0.0 ? time_ago(0.5 * f.trail_time) : "";
  const float bar_w =
      std::min(room, std::max(std::clamp(float(view.width) * 0.3f, 60 * px, 150 * px),
                              gui().text_size(old_end + " " + middle + " now").x * 1.4f));
  const float bar_h = std::max(5.0f, 4.0f * px);
  const float ticks_top = y - font;
  for (const auto& [label, fraction, anchor] :
       {std::tuple{old_end, 0.0f, TextAnchor::bottom_left},
        std::tuple{middle, 0.5f, TextAnchor::bottom},
        std::tuple{std::string("now"), 1.0f, TextAnchor::bottom_right}})
    if (!label.empty()) flat.add_text({{left + fraction * bar_w, y, 0}, label, text, anchor});
  const float bar_bottom = ticks_top - 2 * px, bar_top = bar_bottom - bar_h;
  constexpr int kSteps = 48;
  std::vector<render::ColouredVertex> quads;
  for (int i = 0; i < kSteps; ++i) {
    const float x0 = left + bar_w * float(i) / kSteps, x1 = left + bar_w * float(i + 1) / kSteps;
    // The step's colour at its middle: age 1 at the left end, 0 at the right.
    const float age = 1.0f - (float(i) + 0.5f) / kSteps;
    const glm::vec4 c = age_colour_opaque(age, ink.trail_map_top);
    for (const glm::vec2 p :
         {glm::vec2(x0, bar_top), glm::vec2(x1, bar_top), glm::vec2(x1, bar_bottom),
          glm::vec2(x0, bar_top), glm::vec2(x1, bar_bottom), glm::vec2(x0, bar_bottom)})
      quads.push_back({glm::vec3(p, 0), c});
  }
  flat.add_triangles(quads);
  const Box bar{{left, bar_top}, {left + bar_w, bar_bottom}};
  annotations_.colour_bar = bar;
  taken.push_back({{left, bar_top}, {left + bar_w, y}});
  return taken;
}

std::optional<Box> FramePainter::draw_marks_key(DrawList& flat, const scene::Frame& f,
                                                const render::Camera& camera,
                                                const render::Viewport& view, float px) {
  const scene::Theme& ink = ink_for(f);
  const bool gravity = f.view == scene::View::space && (f.layers.body || f.layers.sphere);
  const bool marks = f.layers.body;
  const bool com = marks && f.body.centre_of_mass.norm() > 1e-4f;
  if ((!gravity && !marks) || view.width < 360) return std::nullopt;
  const glm::vec4 text = to_glm(ink.axis_label);
  const float font = gui().label_font_px();
  const float line = font * 1.3f;
  std::vector<std::string> rows;
  if (gravity) rows.push_back("gravity");
  if (marks) rows.push_back("fixed point");
  if (com) rows.push_back("centre of mass");
  float widest = 0.0f;
  for (const auto& r : rows) widest = std::max(widest, gui().text_size(r).x);
  const float sym = std::max(line, 14 * px);  // the column of symbols
  const float right = float(view.x + view.width) - 8 * px;
  const float x_sym = right - widest - 4 * px - sym * 0.5f, x_text = right - widest;
  // At the view's top right; below the overlay where it floats over that
  // corner (small pictures), and left out where it would then not fit.
  float top = float(view.y) + 8 * px;
  const float height = line * float(rows.size());
  const Box at_top{{x_sym - sym * 0.5f - 2 * px, top}, {right, top + height}};
  if (floating_overlay_ && floating_overlay_->intersects(at_top)) {
    top = floating_overlay_->max.y + 8 * px;
    if (top + height > float(view.y + view.height) * 0.5f) return std::nullopt;
  }
  // Left out rather than drawn over a run's current point.
  const Box placed{{at_top.min.x, top}, {right, top + height}};
  for (const Box& mark : run_mark_boxes(f, camera, view, px))
    if (placed.intersects(mark)) return std::nullopt;
  float y = top + line * 0.5f;
  for (const auto& r : rows) {
    if (r == "gravity") {
      // The direction of gravity (world -z) as the camera sees it.
      const auto o = render::project_to_pixel(camera, view, {0, 0, 0});
      const auto d = render::project_to_pixel(camera, view, {0, 0, -1});
      glm::vec2 dir(0.0f, 1.0f);
      if (o && d && glm::length(glm::vec2(*d) - glm::vec2(*o)) > 1e-3f)
        dir = glm::normalize(glm::vec2(*d) - glm::vec2(*o));
      const float len = sym * 0.9f;
      add_arrow_2d(flat, glm::vec2(x_sym, y) - dir * (len * 0.5f), dir, len, 1.5f * px, text);
    } else {
      const bool fixed = r == "fixed point";
      flat.add_marker(
          {glm::vec3(x_sym, y, 0), to_glm(fixed ? ink.fixed_point_fill : ink.centre_of_mass_fill),
           to_glm(fixed ? ink.fixed_point_edge : ink.centre_of_mass_edge), 4.0f * px, 1.2f * px});
    }
    flat.add_text({{x_text, y, 0}, r, text, TextAnchor::left});
    y += line;
  }
  return Box{{x_sym - sym * 0.5f - 2 * px, top}, {right, top + height}};
}

void FramePainter::draw_view_annotations(const scene::Frame& f, const render::Camera& camera,
                                         const render::Viewport& view, float px) {
  const scene::Theme& ink = ink_for(f);
  auto project = [&](const glm::vec3& w) -> std::optional<glm::vec2> {
    if (auto p = render::project_to_pixel(camera, view, w)) return glm::vec2(*p);
    return std::nullopt;
  };
  DrawList flat;
  std::vector<Box> obstacles = draw_trail_key(flat, f, view, px);
  // A single run's horizon note (paint/comparison_painter.hpp) goes above the
  // trail's key; the labels keep clear of the room it takes.
  float key_top = float(view.y + view.height) - 6 * px;
  for (const Box& b : obstacles) key_top = std::min(key_top, b.min.y);
  annotations_.legend_bottom = key_top - 2 * px;
  if (const int rows = horizon_note_rows(f)) {
    const float height = float(rows) * horizon_note_line(px);
    obstacles.push_back({{float(view.x), *annotations_.legend_bottom - height},
                         {float(view.x) + 0.6f * float(view.width), *annotations_.legend_bottom}});
  }
  annotations_.marks_key = draw_marks_key(flat, f, camera, view, px);
  if (annotations_.marks_key) obstacles.push_back(*annotations_.marks_key);
  if (floating_overlay_) obstacles.push_back(*floating_overlay_);

  // Marks the labels must not cover: the current point, the other runs'
  // (drawn here as diamonds), the fixed point and the centre of mass (these
  // two drawn here, on top of the body that hides them).
  if (f.layers.sphere) {
    if (auto p = project(to_glm(f.current))) {
      annotations_.current_mark = box_around(*p, current_mark_size(px));
      obstacles.push_back(*annotations_.current_mark);
    }
    annotations_.ghosts = draw_ghosts(flat, f, project, px);
    obstacles.insert(obstacles.end(), annotations_.ghosts.begin(), annotations_.ghosts.end());
    // The sphere's outline: the circle where the lines from the eye touch it.
    const glm::vec3 eye = camera.eye_position();
    const float d = glm::length(eye);
    if (d > 1.0f) {
      const glm::vec3 towards = eye / d;
      glm::vec3 side = glm::cross(towards, glm::vec3(0, 0, 1));
      if (glm::length(side) < 1e-3f) side = glm::vec3(1, 0, 0);
      side = glm::normalize(side);
      const auto centre = project(glm::vec3(0.0f));
      const auto edge = project(towards / d + side * std::sqrt(1.0f - 1.0f / (d * d)));
      if (centre && edge)
        annotations_.sphere = PaintedAnnotations::Disc{*centre, glm::length(*edge - *centre)};
    }
  }
  const glm::mat4 rot = glm::mat4_cast(to_glm(f.body_rotation));
  const std::optional<glm::vec2> origin = project(glm::vec3(0.0f));
  if (f.layers.body) {
    const glm::vec3 com = glm::vec3(rot * glm::vec4(to_glm(f.body.centre_of_mass), 1.0f));
    const float r = 4.0f * px;
    if (glm::length(com) > 1e-4f)
      if (auto p = project(com)) {
        flat.add_marker({glm::vec3(*p, 0), to_glm(ink.centre_of_mass_fill),
                         to_glm(ink.centre_of_mass_edge), r, 1.2f * px});
        obstacles.push_back(box_around(*p, glm::vec2(2.0f * r + 2.0f * px)));
      }
    if (origin) {
      flat.add_marker({glm::vec3(*origin, 0), to_glm(ink.fixed_point_fill),
                       to_glm(ink.fixed_point_edge), r, 1.2f * px});
      obstacles.push_back(box_around(*origin, glm::vec2(2.0f * r + 2.0f * px)));
    }
  }

  // Labels at the tips of what they name, pushed outwards from the centre.
  std::vector<LabelRequest> requests;
  std::vector<glm::vec4> colours;
  auto request = [&](const std::string& text, const glm::vec3& tip, const glm::vec4& colour) {
    const auto p = project(tip);
    if (!p) return;
    const glm::vec2 size = gui().text_size(text);
    const glm::vec2 out = origin ? *p - *origin : glm::vec2(0.0f, -1.0f);
    // Next to the tip first; farther out only where everything near is taken
    // (under the overlay window in small pictures).
    auto near = candidates_around(*p, size, out, 2.0f * px);
    for (float ring : {1.0f, 2.5f}) {
      const auto far = candidates_around(*p, size, out, 2.0f * px + ring * size.y);
      near.insert(near.end(), far.begin(), far.end());
    }
    requests.push_back({text, size, std::move(near)});
    colours.push_back(colour);
  };
  if (f.layers.body) {
    const float length = axis_length(f);
    const char* names[] = {"e1", "e2", "e3"};
    for (int i = 0; i < 3; ++i) {
      glm::vec3 axis(0.0f);
      axis[i] = 1.0f;
      request(names[i], glm::vec3(rot * glm::vec4(axis * length, 1.0f)), to_glm(ink.axis_label));
    }
  }
  if (f.layers.sphere) {
    request("N", {0, 0, 1.0f}, to_glm(ink.pole_label));
    request("S", {0, 0, -1.0f}, to_glm(ink.pole_label));
  }
  const Box bounds = box_of(view.inset(int(2 * px), int(2 * px), int(2 * px), int(2 * px)));
  add_placed_labels(flat, requests, colours, obstacles, bounds);
  draw_flat(flat);
}

}  // namespace epviz::paint
