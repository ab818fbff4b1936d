#pragma once
// How runs are told apart in a picture, and what a comparison scene
// (scene::Comparison) and the pixel-true horizon add to it: every run's line
// in its colour and line style (a single run in the time colours), thinner
// and looser after its pixel-true time but never faded; the other runs'
// current points as hollow diamonds (never round, like the centre of mass);
// the edge marks in run colours; the legend in its own strip; the tile
// caption on its own line; the separation chart. Called from FramePainter;
// knows no physics.
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "paint/label_placement.hpp"
#include "render/draw_list.hpp"
#include "render/panel_2d.hpp"
#include "scene/frame.hpp"
#include "scene/layout.hpp"
#include "scene/theme.hpp"

namespace epviz::paint {

// Line widths (times the picture's scale) of the trail on the sphere and the
// path on the plane; after a run's pixel-true time, this fraction of them.
constexpr float kSphereTrailWidth = 2.2f, kPlaneTrailWidth = 1.8f;
constexpr float kUntrueWidthFactor = 0.7f;

// Run `run` (0 = the first) of the frame: its line style (solid for a single
// run), its width from `base`, and its colour at a trail point of this age:
// the run's own, opaque, in a comparison; the theme's time colour alone.
scene::LineStyle run_line_style(const scene::Frame& f, std::size_t run);
float run_line_width(std::size_t run, float base);
glm::vec4 run_line_colour(const scene::Frame& f, std::size_t run, float age,
                          const scene::Theme& ink);
// Where run `run`'s pixel-true time falls on its trail (trail points newer than this age lie after it).
const std::optional<float>& run_untrue_age(const scene::Frame& f, std::size_t run);
// Whether the frame is past run `run`'s pixel-true time (known, and earlier
// than the frame's): only then is its line drawn thin and open after it, and
// only then (for any run) does the legend show that line's key.
bool run_past_pixel_true(const scene::Frame& f, std::size_t run);
bool any_run_past_pixel_true(const scene::Frame& f);

// Every run's trail on the sphere, into the 3D list; `to_pixel` says where a
// point lands on screen (the dashes are measured there).
void draw_trails_3d(render::DrawList& list, const scene::Frame& f, const scene::Theme& ink,
                    float px, const std::function<glm::vec2(const glm::vec3&)>& to_pixel);

// Every run's (a, b) path, its edge marks and the other runs' current points.
struct PlaneMarksDrawn {
  bool any_exit = false, any_infinity = false;
};
PlaneMarksDrawn draw_paths_plane(render::DrawList& flat, const render::Panel2D& plot,
                                 const scene::Frame& f, const scene::Theme& ink, float px);

// A hollow diamond of `radius` pixels, on a halo of the background's colour.
void add_diamond(render::DrawList& flat, glm::vec2 centre, float radius, const glm::vec4& colour,
                 const glm::vec4& halo, float px);
// The room a run's diamond takes (its halo and a gap) at this line scale.
inline glm::vec2 ghost_mark_size(float px) { return glm::vec2(2.0f * 6.5f * px + 4.0f * px); }
// The other runs' current points over the 3D view (image pixels): their boxes.
std::vector<Box> draw_ghosts(
    render::DrawList& flat, const scene::Frame& f,
    const std::function<std::optional<glm::vec2>(const glm::vec3&)>& project, float px);

// What draw_run_annotations drew: the legend's rows, the caption and the
// horizon's note, each with its box.
struct AnnotationBox {
  std::string text;
  Box box;
};
using TextMeasure = std::function<glm::vec2(const std::string&)>;
// The caption in its line, the comparison's legend in its strip
// (layout.legend_area), a single run's horizon note at the 3D view's bottom
// left with its last row's bottom at `note_bottom`, and the separation chart.
// `picture`: the picture's size in pixels, which the runs' pixel-true
// horizons in the legend are of.
std::vector<AnnotationBox> draw_run_annotations(render::DrawList& flat, const scene::Frame& f,
                                                const scene::FrameLayout& layout,
                                                const scene::Theme& ink, float px,
                                                const TextMeasure& measure,
                                                std::optional<float> note_bottom,
                                                glm::ivec2 picture);

// The single run's horizon note, the room it takes over the 3D view: its rows and their height.
int horizon_note_rows(const scene::Frame& f);
float horizon_note_line(float px);

}  // namespace epviz::paint
