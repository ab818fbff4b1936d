#include "paint/comparison_painter.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "paint/painter_common.hpp"
#include "paint/separation_chart.hpp"

namespace epviz::paint {
namespace {

using render::TextAnchor;

// After the horizon the trail is drawn at a third of its opacity: still
// there, visibly not to be trusted.
constexpr float kUntrueAlpha = 0.3f;

bool after_horizon(const std::optional<float>& untrue_age, float age) {
  return untrue_age && age < *untrue_age;
}

// A run's colour at a point of its trail: opaque now, fading with age as the
// time colours do.
glm::vec4 run_point_colour(const scene::Rgba& run, float age, const std::optional<float>& untrue) {
  glm::vec4 c = to_glm(run);
  c.a = 0.25f + 0.75f * (1.0f - age);
  if (after_horizon(untrue, age)) c.a *= kUntrueAlpha;
  return c;
}

// The line width of run `index` (0 = the first, drawn `first` wide).
float stripe_width(std::size_t index, float first) {
  return std::max(0.6f, first * (1.0f - 0.3f * float(index)));
}

}  // namespace

glm::vec4 first_run_colour(const scene::Frame& f, float age, const glm::vec4& time_colour) {
  if (f.comparison && !f.comparison->colours.empty())
    return run_point_colour(f.comparison->colours.front(), age, f.untrue_age);
  glm::vec4 c = time_colour;
  if (after_horizon(f.untrue_age, age)) c.a *= kUntrueAlpha;
  return c;
}

void draw_other_runs_3d(render::DrawList& list, const scene::Frame& f, float px) {
  if (!f.comparison) return;
  const auto& c = *f.comparison;
  for (std::size_t i = 0; i < c.others.size(); ++i) {
    const auto& run = c.others[i];
    const scene::Rgba colour = c.colours[i + 1];
    std::vector<render::LineVertex> trail;
    trail.reserve(run.trail.size());
    for (const auto& p : run.trail)
      trail.push_back({to_glm(p.p), run_point_colour(colour, p.age, run.untrue_age)});
    // Each run thinner than the one before: where runs coincide, all their
    // colours still show, as nested stripes.
    if (trail.size() >= 2) list.add_polyline(trail, stripe_width(i + 1, 2.2f) * px);
    // A ghost: a hollow ring where this run's body points now.
    list.add_marker({to_glm(run.current), {0, 0, 0, 0}, to_glm(colour), 5.5f * px, 1.8f * px});
  }
}

void draw_other_runs_plane(render::DrawList& flat, const render::Panel2D& plot,
                           const scene::Frame& f, float px) {
  if (!f.comparison) return;
  const auto& c = *f.comparison;
  for (std::size_t i = 0; i < c.others.size(); ++i) {
    const auto& run = c.others[i];
    const scene::Rgba colour = c.colours[i + 1];
    std::vector<glm::dvec2> points;
    std::vector<glm::vec4> colours;
    auto flush = [&] {
      if (points.size() >= 2)
        plot.draw_polyline(flat, points, colours, stripe_width(i + 1, 1.8f) * px);
      points.clear();
      colours.clear();
    };
    for (const auto& p : run.plane_path) {
      if (p.break_before) flush();
      points.emplace_back(p.ab.x(), p.ab.y());
      colours.push_back(run_point_colour(colour, p.age, run.untrue_age));
    }
    flush();
    if (run.plane_current)
      plot.draw_marker(flat, {run.plane_current->x(), run.plane_current->y()},
                       {{}, {0, 0, 0, 0}, to_glm(colour), 4.5f * px, 1.6f * px});
  }
}

std::vector<std::pair<std::string, glm::vec4>> run_legend_rows(const scene::Frame& f,
                                                               const scene::Theme& ink) {
  // Rows from the bottom up: the horizon's note (single run), then the legend.
  std::vector<std::pair<std::string, glm::vec4>> rows;
  if (f.comparison) {
    const auto& c = *f.comparison;
    for (std::size_t i = 0; i < c.labels.size(); ++i) {
      std::string row = std::to_string(i + 1) + "  " + c.labels[i];
      const auto& until = i == 0 ? f.pixel_true_until : c.others[i - 1].pixel_true_until;
      if (until) {
        char note[64];
        std::snprintf(note, sizeof note, "  (pixel-true to t = %.3g)", *until);
        row += note;
      }
      rows.emplace_back(std::move(row), to_glm(c.colours[i]));
    }
    if (f.pixel_true_until || std::any_of(c.others.begin(), c.others.end(),
                                          [](const auto& r) { return r.pixel_true_until; }))
      rows.emplace_back("faded: after a run's pixel-true time", to_glm(ink.trail_caption));
  } else if (!f.pixel_true_note.empty()) {
    rows.emplace_back(f.pixel_true_note, to_glm(ink.drift_warn));
  }
  return rows;
}

float run_legend_line(float px) { return 15.0f * px; }

bool draw_run_annotations(render::DrawList& flat, const scene::Frame& f,
                          const scene::FrameLayout& layout, const scene::Theme& ink, float px,
                          std::optional<float> rows_bottom) {
  const auto rows = run_legend_rows(f, ink);
  const bool chart = f.comparison && layout.chart_area;
  if (rows.empty() && !chart && f.caption.empty()) return false;
  if (!f.caption.empty()) {
    // At the top right, above the plane's title: the bottom right holds the
    // plane's convention, the bottom left the trail's key and the legend,
    // the top left the overlay.
    int right = 0, top = 1 << 30;
    for (const auto& r : {layout.view_3d, layout.panel_column})
      if (r) right = std::max(right, r->right()), top = std::min(top, r->y);
    render::TextLabel label{{float(right) - 6.0f * px, float(top) + 3.0f * px, 0.0f},
                            f.caption,
                            to_glm(ink.title),
                            TextAnchor::top_right};
    label.background = to_glm(ink.panel_background);
    label.background.a = 0.85f;
    flat.add_text(std::move(label));
  }

  if (!rows.empty() && (layout.view_3d || layout.panel_column)) {
    const scene::Rect where = layout.view_3d ? *layout.view_3d : *layout.panel_column;
    // Above the trail's key (its caption and colour bar) at the view's bottom
    // left, each row on a box of the panel's colour so that it reads over the
    // sphere's lines.
    const float line = run_legend_line(px);
    float y = rows_bottom.value_or(float(where.bottom()) - 6.0f * px - 1.3f * line);
    for (auto it = rows.rbegin(); it != rows.rend(); ++it, y -= line) {
      render::TextLabel label{
          {float(where.x) + 8.0f * px, y, 0.0f}, it->first, it->second, TextAnchor::bottom_left};
      label.background = to_glm(ink.panel_background);
      label.background.a = 0.8f;
      flat.add_text(std::move(label));
    }
  }
  if (chart) draw_separation_chart(flat, *f.comparison, *layout.chart_area, ink, px);
  return true;
}

}  // namespace epviz::paint
