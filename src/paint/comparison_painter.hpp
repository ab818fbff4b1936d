#pragma once
// What a comparison scene (scene::Comparison) and the pixel-true horizon add
// to the painter's picture: the runs' own colours, the other runs' trails and
// ghost markers, the legend, the separation chart and the horizon's note.
// Called from FramePainter at a few hooks; knows no physics.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec4.hpp>

#include "render/draw_list.hpp"
#include "render/panel_2d.hpp"
#include "scene/frame.hpp"
#include "scene/layout.hpp"
#include "scene/theme.hpp"

namespace epviz::paint {

// The colour of a point of the first run's trail, given its time colour:
// the run's own colour in a comparison scene (fading with age as the time
// colours do), and faded further after the run's pixel-true horizon.
glm::vec4 first_run_colour(const scene::Frame& f, float age, const glm::vec4& time_colour);

// The other runs' trails on the sphere and their current points as ghost
// markers (hollow rings in their colours), into the 3D list.
void draw_other_runs_3d(render::DrawList& list, const scene::Frame& f, float px);
// Their (a, b) paths and current points in the plane's plot.
void draw_other_runs_plane(render::DrawList& flat, const render::Panel2D& plot,
                           const scene::Frame& f, float px);

// The rows of the legend (one per run, in its colour) or of a single run's
// horizon note, bottom row last; and the height of one row.
std::vector<std::pair<std::string, glm::vec4>> run_legend_rows(const scene::Frame& f,
                                                               const scene::Theme& ink);
float run_legend_line(float px);

// The legend and the horizon's note at the 3D view's bottom left, their last
// row's bottom at `rows_bottom` (above the trail's key; default: above its
// caption line), and, under the plane, the separation chart
// (paint/separation_chart.hpp). Into a 2D list; false when the frame has none of these.
bool draw_run_annotations(render::DrawList& flat, const scene::Frame& f,
                          const scene::FrameLayout& layout, const scene::Theme& ink, float px,
                          std::optional<float> rows_bottom = std::nullopt);

}  // namespace epviz::paint
