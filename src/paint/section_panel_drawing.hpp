#pragma once
// Draws a frame's section panel (scene::SectionPanel): a square plot of the
// crossings so far, a dot each in its run's colour, the newest of each run
// marked, the surface and sheet in the title, the coordinates' symbols on
// the axes and the count of crossings on the sheet not shown.
// Plain values in, a 2D draw list out: no physics here.
#include <functional>
#include <optional>
#include <string>

#include <glm/vec2.hpp>

#include "render/draw_list.hpp"
#include "render/panel_2d.hpp"
#include "scene/frame.hpp"
#include "scene/theme.hpp"

namespace epviz::paint {

// The square plots' look in a frame's column (the Riccati plane's and the
// section's): the theme's panel colours, lines and ticks at the picture's scale `px`.
render::PanelStyle column_panel_style(const scene::Theme& ink, float px);

// The panel into `area` (layout.section_area), its title above and its tick
// labels and x title below. `measure` gives a text's size in pixels.
void draw_section_panel(render::DrawList& flat, const scene::SectionPanel& panel,
                        const render::Viewport& area, const scene::Theme& ink, float px,
                        const std::function<glm::vec2(const std::string&)>& measure);

// The inverse of the panel's plot: the data point (x on axes[0], y on
// axes[1]) under image pixel (x, y) of the panel drawn into `area`, or
// nullopt off its plot (a click there is no point of the section).
std::optional<glm::dvec2> section_point_at(const scene::SectionPanel& panel,
                                           const render::Viewport& area, float x, float y);

}  // namespace epviz::paint
