#include "paint/section_panel_drawing.hpp"

#include <algorithm>
#include <vector>

#include "paint/figure_common.hpp"
#include "paint/painter_common.hpp"

namespace epviz::paint {

render::PanelStyle column_panel_style(const scene::Theme& ink, float px) {
  render::PanelStyle style;
  style.background = to_glm(ink.panel_background);
  style.frame = to_glm(ink.panel_frame);
  style.grid = to_glm(ink.panel_grid);
  style.axis = to_glm(ink.panel_axis);
  style.text = to_glm(ink.panel_text);
  style.tick_length = 4.0f * px;
  style.frame_width = style.axis_width = 1.0f * px;
  style.min_tick_spacing_px = 34.0f * px;
  return style;
}

void draw_section_panel(render::DrawList& flat, const scene::SectionPanel& panel,
                        const render::Viewport& area, const scene::Theme& ink, float px,
                        const std::function<glm::vec2(const std::string&)>& measure) {
  const auto& r = panel.range;
  // Each axis its own scale (section_point_at inverts this plot): the coordinates may be of different kinds (an
  // angular velocity against a component of gamma).
  const render::Panel2D plot(area, {r[0], r[1], r[2], r[3]}, false);
  render::PanelStyle style = column_panel_style(ink, px);
  style.axis = {0, 0, 0, 0};  // the lines through 0 mean nothing special here
  draw_axes_in_print(plot, flat, style);

  // The dots, each run's oldest first and the runs from the last to the
  // first, so that the first run's lie on top.
  auto colour_of = [&](std::size_t run) {
    return panel.colours.empty() ? glm::vec4(1.0f)
                                 : to_glm(panel.colours[std::min(run, panel.colours.size() - 1)]);
  };
  const float dot = 2.0f * px;
  std::vector<render::ColouredVertex> dots;
  for (std::size_t i = panel.runs.size(); i-- > 0;) {
    const glm::vec4 colour = colour_of(i);
    for (const auto& p : panel.runs[i])
      dots.push_back({glm::vec3(plot.to_pixel({p.x(), p.y()}), 0.0f), colour});
  }
  if (!dots.empty()) flat.add_dots(dots, dot);
  // The newest crossing of each run: a ringed marker in its colour.
  for (std::size_t i = panel.runs.size(); i-- > 0;) {
    if (panel.runs[i].empty()) continue;
    const auto& p = panel.runs[i].back();
    plot.draw_marker(flat, {p.x(), p.y()},
                     {{}, colour_of(i), to_glm(ink.marker_edge), 4.0f * px, 1.2f * px});
  }

  // Above: the longest wording that fits over the plot (the surface alone
  // at the least; it may then reach into the margins beside the plot).
  std::string title = panel.title;
  for (const std::string& longer : {"Poincaré section " + panel.title, "section " + panel.title})
    if (measure(longer).x <= float(area.width)) {
      title = longer;
      break;
    }
  plot.draw_text(flat, {0.5 * (r[0] + r[1]), r[3]},
                 {{}, title, style.text, render::TextAnchor::bottom, {0, -6 * px}});
  // The axes' titles inside the plot's corners, x at the bottom right and y
  // at the top left, on the panel's background so that no dot hides them
  // (under the plot the plane's caption may run across).
  flat.add_text({glm::vec3(float(area.x + area.width) - 3.0f * px,
                           float(area.y + area.height) - 2.0f * px, 0),
                 panel.axes[0],
                 style.text,
                 render::TextAnchor::bottom_right,
                 {0, 0},
                 style.background});
  flat.add_text({glm::vec3(float(area.x) + 3.0f * px, float(area.y) + 2.0f * px, 0),
                 panel.axes[1],
                 style.text,
                 render::TextAnchor::top_left,
                 {0, 0},
                 style.background});
  // The crossings on the sheet not shown, counted under the tick labels
  // (outside the plot, where it hides no dot), so that the plot does not
  // pass for every crossing there is.
  // A note wider than the plot ends at its right edge (the frame's, in a
  // column) and reaches left under the gap between the plots.
  if (!panel.note.empty()) {
    const glm::vec2 size = measure(panel.note);
    const bool fits = size.x <= float(area.width);
    const float y = float(area.y + area.height) + 10.0f * px + size.y;
    const float x = fits ? float(area.x) + 0.5f * float(area.width) : float(area.x + area.width);
    flat.add_text({glm::vec3(x, y, 0),
                   panel.note,
                   style.text,
                   fits ? render::TextAnchor::top : render::TextAnchor::top_right,
                   {0, 0}});
  }
}

std::optional<glm::dvec2> section_point_at(const scene::SectionPanel& panel,
                                           const render::Viewport& area, float x, float y) {
  if (area.width <= 0 || area.height <= 0) return std::nullopt;
  const double u = (double(x) - area.x) / area.width;
  const double v = 1.0 - (double(y) - area.y) / area.height;  // pixel rows run down
  if (!(u >= 0.0 && u <= 1.0 && v >= 0.0 && v <= 1.0)) return std::nullopt;
  const auto& r = panel.range;
  return glm::dvec2(r[0] + u * (r[1] - r[0]), r[2] + v * (r[3] - r[2]));
}

}  // namespace epviz::paint
