#include "paint/comparison_painter.hpp"

#include <algorithm>
#include <cstdio>
#include <span>
#include <string>
#include <vector>

#include "paint/dash_pattern.hpp"
#include "paint/painter_common.hpp"
#include "paint/separation_chart.hpp"
#include "paint/trail_colours.hpp"
#include "physics/notation.hpp"

namespace epviz::paint {
namespace {

using render::TextAnchor;

std::size_t run_count(const scene::Frame& f) {
  return f.comparison ? f.comparison->labels.size() : 1;
}

// Draws `vertices` (oldest first, with their ages and places on screen) in a
// line style: the part before the pixel-true time as the style asks, the part
// after it thinner and looser. `draw` takes each piece and its width.
template <class V, class Lerp, class Draw>
void draw_styled(std::span<const V> vertices, std::span<const glm::vec2> pixels,
                 std::span<const float> ages, const std::optional<float>& untrue_age,
                 scene::LineStyle style, float width, Lerp lerp, Draw draw) {
  if (vertices.size() < 2) return;
  // The first vertex after the horizon (ages fall towards now).
  std::size_t k = vertices.size();
  if (untrue_age)
    for (std::size_t i = 0; i < ages.size(); ++i)
      if (ages[i] < *untrue_age) {
        k = i;
        break;
      }
  auto part = [&](std::size_t from, std::size_t to, bool open) {  // vertices [from, to)
    if (to - from < 2) return;
    const float w = open ? width * kUntrueWidthFactor : width;
    const auto pattern = dash_pattern(style, w, open);
    const auto v = vertices.subspan(from, to - from);
    for (const auto& s : dash_spans(pixels.subspan(from, to - from), pattern))
      draw(span_vertices(v, s, lerp), w);
  };
  // The two parts share the vertex before the horizon, so the line is unbroken.
  const std::size_t split = k == 0 ? 0 : k - 1;
  part(0, std::min(k, vertices.size()), false);
  part(split, vertices.size(), true);
}

render::LineVertex lerp_3d(const render::LineVertex& a, const render::LineVertex& b, float s) {
  return {a.position + (b.position - a.position) * s, a.colour + (b.colour - a.colour) * s};
}

struct PlaneVertex {
  glm::dvec2 ab;
  glm::vec4 colour;
};
PlaneVertex lerp_plane(const PlaneVertex& a, const PlaneVertex& b, float s) {
  return {a.ab + (b.ab - a.ab) * double(s), a.colour + (b.colour - a.colour) * s};
}

const std::vector<scene::TrailPoint>& trail_of(const scene::Frame& f, std::size_t run) {
  return run == 0 ? f.trail : f.comparison->others[run - 1].trail;
}
const std::vector<scene::PlanePoint>& plane_path_of(const scene::Frame& f, std::size_t run) {
  return run == 0 ? f.plane_path : f.comparison->others[run - 1].plane_path;
}
const std::vector<scene::PlaneMark>& plane_marks_of(const scene::Frame& f, std::size_t run) {
  return run == 0 ? f.plane_marks : f.comparison->others[run - 1].plane_marks;
}
const std::optional<double>& pixel_true_until_of(const scene::Frame& f, std::size_t run) {
  return run == 0 ? f.pixel_true_until : f.comparison->others[run - 1].pixel_true_until;
}

// The age on run `run`'s trail after which its line is drawn thin and open:
// none while the frame has not passed the run's pixel-true time.
std::optional<float> thin_after(const scene::Frame& f, std::size_t run) {
  return run_past_pixel_true(f, run) ? run_untrue_age(f, run) : std::nullopt;
}

// A 2D sample of a run's line, `length` pixels from `from`, in its style.
void add_line_sample(render::DrawList& flat, glm::vec2 from, float length, scene::LineStyle style,
                     float width, bool open, const glm::vec4& colour) {
  const glm::vec2 ends[2] = {from, from + glm::vec2(length, 0.0f)};
  for (const auto& s : dash_spans(ends, dash_pattern(style, width, open))) {
    const glm::vec2 a = ends[0] + (ends[1] - ends[0]) * s.from.fraction;
    const glm::vec2 b = ends[0] + (ends[1] - ends[0]) * s.to.fraction;
    flat.add_line(glm::vec3(a, 0.0f), glm::vec3(b, 0.0f), colour, width);
  }
}

// The run's pixel-true horizon, and where it fits, the picture size it
// holds for (a larger picture has an earlier one).
std::string until_note(double until, int width = 0, int height = 0) {
  char note[96];
  if (width > 0)
    std::snprintf(note, sizeof note, "  (pixel-true to t = %.3g at %d×%d)", until, width, height);
  else
    std::snprintf(note, sizeof note, "  (pixel-true to t = %.3g)", until);
  return note;
}

// The text cut (with "...") to fit `room` pixels.
std::string fitted(std::string text, float room, const TextMeasure& measure) {
  if (measure(text).x <= room) return text;
  while (!text.empty() && measure(text + "...").x > room) {
    // A whole character at a time: UTF-8's continuation bytes go with their lead.
    while (text.size() > 1 && (static_cast<unsigned char>(text.back()) & 0xC0) == 0x80)
      text.pop_back();
    text.pop_back();
  }
  return text.empty() ? text : text + "...";
}

}  // namespace

scene::LineStyle run_line_style(const scene::Frame& f, std::size_t run) {
  if (!f.comparison || run >= f.comparison->lines.size()) return scene::LineStyle::solid;
  return f.comparison->lines[run];
}

float run_line_width(std::size_t /*run*/, float base) {
  // All runs as wide: where runs coincide, a later run's dashes cover the
  // earlier runs' line and its gaps show them, every colour in turn.
  return base;
}

glm::vec4 run_line_colour(const scene::Frame& f, std::size_t run, float age,
                          const scene::Theme& ink) {
  if (f.comparison && run < f.comparison->colours.size()) return to_glm(f.comparison->colours[run]);
  return age_colour(age, ink.trail_map_top, ink.trail_oldest_alpha);
}

const std::optional<float>& run_untrue_age(const scene::Frame& f, std::size_t run) {
  return run == 0 ? f.untrue_age : f.comparison->others[run - 1].untrue_age;
}

bool run_past_pixel_true(const scene::Frame& f, std::size_t run) {
  const auto& until = pixel_true_until_of(f, run);
  return until && *until < f.t;
}

bool any_run_past_pixel_true(const scene::Frame& f) {
  for (std::size_t r = 0; r < run_count(f); ++r)
    if (run_past_pixel_true(f, r)) return true;
  return false;
}

void draw_trails_3d(render::DrawList& list, const scene::Frame& f, const scene::Theme& ink,
                    float px, const std::function<glm::vec2(const glm::vec3&)>& to_pixel) {
  for (std::size_t r = 0; r < run_count(f); ++r) {
    const auto& trail = trail_of(f, r);
    std::vector<render::LineVertex> vertices;
    std::vector<glm::vec2> pixels;
    std::vector<float> ages;
    for (const auto& p : trail) {
      vertices.push_back({to_glm(p.p), run_line_colour(f, r, p.age, ink)});
      pixels.push_back(to_pixel(to_glm(p.p)));
      ages.push_back(p.age);
    }
    draw_styled<render::LineVertex>(vertices, pixels, ages, thin_after(f, r), run_line_style(f, r),
                                    run_line_width(r, kSphereTrailWidth * px), lerp_3d,
                                    [&](const std::vector<render::LineVertex>& piece, float w) {
                                      list.add_polyline(piece, w);
                                    });
  }
}

void add_diamond(render::DrawList& flat, glm::vec2 centre, float radius, const glm::vec4& colour,
                 const glm::vec4& halo, float px) {
  auto ring = [&](float r) {
    return std::vector<glm::vec3>{
        glm::vec3(centre + glm::vec2(0, -r), 0), glm::vec3(centre + glm::vec2(r, 0), 0),
        glm::vec3(centre + glm::vec2(0, r), 0), glm::vec3(centre + glm::vec2(-r, 0), 0)};
  };
  flat.add_polyline(ring(radius), halo, 3.4f * px, true);
  flat.add_polyline(ring(radius), colour, 1.8f * px, true);
}

std::vector<Box> draw_ghosts(
    render::DrawList& flat, const scene::Frame& f,
    const std::function<std::optional<glm::vec2>(const glm::vec3&)>& project, float px) {
  std::vector<Box> boxes;
  if (!f.comparison || !f.layers.sphere) return boxes;
  const auto& c = *f.comparison;
  const float r = 6.5f * px;
  for (std::size_t i = 0; i < c.others.size(); ++i)
    if (auto p = project(to_glm(c.others[i].current))) {
      add_diamond(flat, *p, r, to_glm(c.colours[i + 1]), to_glm(f.colours.background), px);
      boxes.push_back(box_around(*p, ghost_mark_size(px)));
    }
  return boxes;
}

PlaneMarksDrawn draw_paths_plane(render::DrawList& flat, const render::Panel2D& plot,
                                 const scene::Frame& f, const scene::Theme& ink, float px) {
  PlaneMarksDrawn drawn;
  for (std::size_t r = 0; r < run_count(f); ++r) {
    // The path, in pieces that do not join across a pass through infinity.
    const auto& path = plane_path_of(f, r);
    const float width = run_line_width(r, kPlaneTrailWidth * px);
    std::vector<PlaneVertex> vertices;
    std::vector<glm::vec2> pixels;
    std::vector<float> ages;
    auto flush = [&] {
      draw_styled<PlaneVertex>(vertices, pixels, ages, thin_after(f, r), run_line_style(f, r),
                               width, lerp_plane,
                               [&](const std::vector<PlaneVertex>& piece, float w) {
                                 std::vector<glm::dvec2> points;
                                 std::vector<glm::vec4> colours;
                                 for (const auto& v : piece) {
                                   points.push_back(v.ab);
                                   colours.push_back(v.colour);
                                 }
                                 plot.draw_polyline(flat, points, colours, w);
                               });
      vertices.clear();
      pixels.clear();
      ages.clear();
    };
    for (const auto& p : path) {
      if (p.break_before) flush();
      const glm::dvec2 ab(p.ab.x(), p.ab.y());
      vertices.push_back({ab, run_line_colour(f, r, p.age, ink)});
      pixels.push_back(plot.to_pixel(ab));
      ages.push_back(p.age);
    }
    flush();

    // Its marks, in the run's colour (the time colour for a single run).
    for (const auto& m : plane_marks_of(f, r)) {
      const glm::dvec2 at(m.ab.x(), m.ab.y());
      glm::vec4 c = run_line_colour(f, r, m.age, ink);
      c.a = 1.0f;
      switch (m.kind) {
        case scene::PlaneMark::Kind::leaves_panel:  // hollow: the path goes on outside
          plot.draw_marker(flat, at, {{}, {0, 0, 0, 0}, c, 4.0f * px, 1.5f * px});
          drawn.any_exit = true;
          break;
        case scene::PlaneMark::Kind::enters_panel:  // filled: the path comes back
          plot.draw_marker(flat, at, {{}, c, c, 3.0f * px, 0.0f});
          drawn.any_exit = true;
          break;
        case scene::PlaneMark::Kind::through_infinity:
          // The first run's pass is marked and named; the others' passes,
          // where they agree, are the same, and near the pole their last
          // direction says little of where the mark should go.
          if (r == 0) {
            plot.draw_marker(flat, at,
                             {{}, {0, 0, 0, 0}, to_glm(ink.infinity_mark), 6.0f * px, 2.0f * px});
            plot.draw_text(flat, at,
                           {{},
                            std::string(physics::symbol::infinity),
                            to_glm(ink.infinity_label),
                            TextAnchor::centre,
                            {0.0f, -11.0f * px}});
            drawn.any_infinity = true;
          }
          break;
      }
    }
    if (r > 0)
      if (const auto& now = f.comparison->others[r - 1].plane_current)
        add_diamond(flat, plot.to_pixel({now->x(), now->y()}), 5.0f * px,
                    to_glm(f.comparison->colours[r]), to_glm(ink.panel_background), px);
  }
  return drawn;
}

int horizon_note_rows(const scene::Frame& f) {
  return !f.comparison && !f.pixel_true_note.empty() ? 1 : 0;
}

float horizon_note_line(float px) { return 15.0f * px; }

std::vector<AnnotationBox> draw_run_annotations(render::DrawList& flat, const scene::Frame& f,
                                                const scene::FrameLayout& layout,
                                                const scene::Theme& ink, float px,
                                                const TextMeasure& measure,
                                                std::optional<float> note_bottom,
                                                glm::ivec2 picture) {
  std::vector<AnnotationBox> drawn;
  auto add_text = [&](glm::vec2 left_middle, const std::string& text, const glm::vec4& colour) {
    const glm::vec2 size = measure(text);
    flat.add_text({glm::vec3(left_middle, 0.0f), text, colour, TextAnchor::left});
    return Box{left_middle - glm::vec2(0.0f, 0.5f * size.y),
               left_middle + glm::vec2(size.x, 0.5f * size.y)};
  };

  if (!f.caption.empty() && layout.caption_area) {
    // Its own line across the top: it covers no key and no part of the sphere.
    const scene::Rect& a = *layout.caption_area;
    const glm::vec2 at(float(a.x) + 8.0f * px, float(a.y) + 0.5f * float(a.height));
    const std::string text = fitted(f.caption, float(a.width) - 16.0f * px, measure);
    drawn.push_back({text, add_text(at, text, to_glm(ink.title))});
  }

  if (f.comparison && layout.legend_area) {
    // One row per run: a sample of its line ending in the mark of its current
    // point (the first run's dot, the others' diamonds), then its name.
    const auto& c = *f.comparison;
    const scene::Rect& a = *layout.legend_area;
    const int rows = scene::comparison_legend_rows(int(c.labels.size()));
    const float line = float(a.height) / float(rows);
    const float x0 = float(a.x) + 8.0f * px, sample = 30.0f * px, mark = 7.0f * px;
    const float text_x = x0 + sample + mark + 6.0f * px;
    const float room = float(a.right()) - 6.0f * px - text_x;
    float y = float(a.y) + 0.5f * line;
    for (std::size_t i = 0; i < c.labels.size(); ++i, y += line) {
      const glm::vec4 colour = to_glm(c.colours[i]);
      add_line_sample(flat, {x0, y}, sample, run_line_style(f, i),
                      run_line_width(i, kSphereTrailWidth * px), false, colour);
      const glm::vec2 end(x0 + sample + 0.5f * mark, y);
      if (i == 0)
        flat.add_marker({glm::vec3(end, 0), to_glm(f.colours.marker), to_glm(ink.marker_edge),
                         5.0f * px, 1.3f * px});
      else
        add_diamond(flat, end, 5.5f * px, colour, to_glm(f.colours.background), px);
      std::string text = std::to_string(i + 1) + "  " + c.labels[i];
      if (const auto& until = pixel_true_until_of(f, i)) {
        for (const std::string& with_note :
             {text + until_note(*until, picture.x, picture.y), text + until_note(*until)})
          if (measure(with_note).x <= room) {
            text = with_note;
            break;
          }
      }
      text = fitted(text, room, measure);
      Box box = add_text({text_x, y}, text, colour);
      box.min.x = x0;
      drawn.push_back({text, box});
    }
    const glm::vec4 grey = to_glm(ink.trail_caption);
    // The key of the thin, open line only where some run is drawn so: a
    // picture that is pixel-true throughout (or a run with no measured
    // horizon) does not send the reader looking for it. Its room stays
    // reserved (the layout is the same in every frame), the caption moves up.
    if (any_run_past_pixel_true(f)) {
      add_line_sample(flat, {x0, y}, sample, scene::LineStyle::solid, kSphereTrailWidth * px, true,
                      grey);
      const std::string key =
          fitted("thin, open line: after the run's pixel-true time", room, measure);
      Box box = add_text({text_x, y}, key, grey);
      box.min.x = x0;
      drawn.push_back({key, box});
      y += line;
    }
    // The trail's caption, shorter where the strip is narrow.
    const float wide = float(a.right()) - 6.0f * px - x0;
    std::string text = "trail: " + f.trail_label + ", one colour and line per run";
    if (measure(text).x > wide) text = fitted("trail: " + f.trail_label, wide, measure);
    drawn.push_back({text, add_text({x0, y}, text, grey)});
  }

  if (horizon_note_rows(f) && (layout.view_3d || layout.panel_column)) {
    // A single run's horizon: a note at the 3D view's bottom left, above the
    // trail's key, on a box of the panel's colour so that it reads over the sphere.
    const scene::Rect where = layout.view_3d ? *layout.view_3d : *layout.panel_column;
    const float y =
        note_bottom.value_or(float(where.bottom()) - 6.0f * px - 1.3f * horizon_note_line(px));
    render::TextLabel label{{float(where.x) + 8.0f * px, y, 0.0f},
                            f.pixel_true_note,
                            to_glm(ink.drift_warn),
                            TextAnchor::bottom_left};
    label.background = to_glm(ink.panel_background);
    label.background.a = 0.8f;
    const glm::vec2 size = measure(f.pixel_true_note);
    drawn.push_back(
        {f.pixel_true_note, {{label.position.x, y - size.y}, {label.position.x + size.x, y}}});
    flat.add_text(std::move(label));
  }
  if (f.comparison && layout.chart_area)
    draw_separation_chart(flat, *f.comparison, *layout.chart_area, ink, px, measure);
  return drawn;
}

}  // namespace epviz::paint
