#pragma once
// Draws a scene::Frame with the render toolkit: the body, the sphere with its
// trail, the Riccati (a, b) plane and the ImGui overlay, each a layer the frame
// switches on or off. The painter reads plain values; it knows no physics.
#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "paint/label_placement.hpp"
#include "render/gl_context.hpp"
#include "render/gpu_mesh.hpp"
#include "render/image.hpp"
#include "render/panel_2d.hpp"
#include "render/renderer.hpp"
#include "scene/frame.hpp"
#include "scene/layout.hpp"

namespace epviz::paint {

struct PainterOptions {
  // Multisampling smooths mesh edges; lines and markers are anti-aliased by
  // their shaders either way, and the box's edges are drawn as such lines, so
  // the default is none: 4x costs about 13 ms a 720p frame on llvmpipe.
  int msaa_samples = 0;
  // ImGui's built-in font instead of a system TTF (snapshot tests use it so
  // that pictures do not depend on the fonts a machine has).
  bool builtin_font = false;
};

// The render toolkit's viewport for a rectangle of scene::frame_layout (both
// count pixels from the top left).
inline render::Viewport to_viewport(const scene::Rect& r) { return {r.x, r.y, r.width, r.height}; }

// Where each part of a frame goes: scene::frame_layout, the one layout (the
// plan uses it too), for the frame's request. `reserved_left` pixels at the left
// edge are kept free (the interactive panels sit there); the layout fills the rest.
scene::FrameLayout layout_for(const scene::Frame& frame, int width, int height,
                              int reserved_left = 0);
// The rectangles only (the pixel scales as for the default camera and panel extent).
scene::FrameLayout layout_for(const scene::Layers& layers, const scene::OverlayText& overlay,
                              int width, int height, int reserved_left = 0);
// How many of the overlay's lines fit a picture of this height.
int overlay_lines_shown(const scene::OverlayText& overlay, int height);
// The camera the painter uses for the 3D view of `frame`.
render::Camera camera_for(const scene::Frame& frame, const render::Viewport& view);

// What the last paint() placed over the picture, for checks: every label of
// the 3D view and the plane with its box, and the trail's colour bar.
struct PaintedAnnotations {
  struct Label {
    std::string text;
    Box box;
    Box bounds;  // the part of the picture it must stay inside
  };
  std::vector<Label> labels;
  std::optional<Box> colour_bar;  // left end oldest (age 1), right end now
  float map_top = 1.0f;           // the theme's top of the time colour map
  float font_px = 0.0f;           // the labels' text height
  // Where the horizon note of a single run ends, above the trail's key (3D view only).
  std::optional<float> legend_bottom;
  // What paint/comparison_painter placed: a comparison's legend rows, the
  // caption, a single run's horizon note (`bounds` unset).
  std::vector<Label> legend;
  // The sphere's outline on screen: centre and radius in pixels.
  struct Disc {
    glm::vec2 centre{0.0f};
    float radius = 0.0f;
  };
  std::optional<Disc> sphere;
  // The other runs' current points (diamonds) over the 3D view.
  std::vector<Box> ghosts;
  // The (first) run's current point over the 3D view, as the labels keep clear of it.
  std::optional<Box> current_mark;
  // The key of the marks (gravity, fixed point, centre of mass) at the 3D view's top right.
  std::optional<Box> marks_key;
  // The overlay window (title, lines, drift table), where the overlay layer is on.
  std::optional<Box> overlay_window;
};

class FramePainter {
 public:
  // `context` must outlive the painter; it is made current here.
  // `page`: the type's size and the parts' arrangement (scene::PageLayout);
  // the frames painted must have the same (their text is set in its font).
  FramePainter(render::GlContext& context, int width, int height, PainterOptions options = {},
               scene::PageLayout page = {});
  ~FramePainter();

  void resize(int width, int height);
  // Keeps a strip at the left edge free of the scene (see layout_for).
  void set_reserved_left(int pixels) { reserved_left_ = pixels; }
  int width() const;
  int height() const;

  // The frame's picture; valid until the next call. `extra_ui` (interactive
  // panels) runs inside the same ImGui frame as the overlay layer.
  const render::RgbaImage& paint(const scene::Frame& frame,
                                 const std::function<void()>& extra_ui = {});
  // The ImGui overlay, for feeding it input and its clock.
  render::ImGuiOverlay& gui();
  // The overlay's framebuffer scale: ImGui's units are frame pixels / this.
  float layout_scale();
  const PaintedAnnotations& annotations() const { return annotations_; }
  // For vector stills (vector/frame_still.hpp): while set, paint() draws only
  // the 3D view with GL and hands every 2D list over it and beside it (marks,
  // labels, keys, the plane, the charts) to `sink` instead, in drawing order;
  // the overlay window is left out (annotations().overlay_window says where
  // it goes). An empty sink: GL draws everything again.
  void set_flat_sink(std::function<void(const render::DrawList&)> sink) {
    flat_sink_ = std::move(sink);
  }
  // The overlay's drift table as draw_info_window writes it: its heading and
  // the key of its colours (for vector stills).
  static const char* drift_table_heading(const scene::Frame& f);
  static std::array<std::string, 3> drift_table_key() { return drift_key(); }
  // Where its values start, from the left of the window's text: after the
  // widest name (at least 12 characters of the bitmap font) and a spacing.
  float drift_table_values_x(const scene::Frame& f);
  // What its value columns measure, written over them on the heading's row:
  // the drawn states, and the integrator's steps where the frame has them.
  static std::vector<std::string> drift_table_columns(const scene::Frame& f);
  // A row's values, one per column; and how far apart the columns start.
  static std::vector<std::string> drift_table_row(const scene::Frame& f, std::size_t row);
  float drift_table_column_width();
  // A small picture's drift table in one line (scene::overlay_drifts_in_one_line):
  // the largest drift named, over the drawn states and where the frame has
  // it at the steps ("drift C₁ 2.6×10⁻⁴ drawn, 8.0×10⁻¹⁶ steps"),
  // in pieces: a value's piece is coloured by its drift, the others are not.
  struct DriftPiece {
    std::string text;
    std::optional<double> drift;
  };
  static std::vector<DriftPiece> drift_line(const scene::Frame& f);

 private:
  void draw_body(render::DrawList& list, const scene::Frame& f, float px);
  void draw_sphere(render::DrawList& list, const scene::Frame& f, const render::Camera& camera,
                   const render::Viewport& view, float px) const;
  // Over the 3D view, in image pixels and after it (so never hidden by the
  // body): the fixed point and the centre of mass, the labels of the axes and
  // poles placed clear of each other, the key, the colour bar and the caption.
  // Where each run's current point is drawn over the 3D view (the first
  // run's, then the others'), with the room the labels leave around it.
  // The overlay window of `size` floating over the 3D view `where`, clear of
  // the runs' points where it can be.
  Box floating_window_box(const scene::Frame& f, const scene::Rect& where, glm::vec2 size,
                          float px);
  static std::vector<Box> run_mark_boxes(const scene::Frame& f, const render::Camera& camera,
                                         const render::Viewport& view, float px);
  void draw_view_annotations(const scene::Frame& f, const render::Camera& camera,
                             const render::Viewport& view, float px);
  // The time colour bar and the trail's caption along the view's bottom edge;
  // returns the boxes they take (for the labels to keep clear of).
  std::vector<Box> draw_trail_key(render::DrawList& flat, const scene::Frame& f,
                                  const render::Viewport& view, float px);
  // The key in the view's top right corner: gravity (space view), fixed
  // point, centre of mass; returns its box (empty where none is drawn).
  std::optional<Box> draw_marks_key(render::DrawList& flat, const scene::Frame& f,
                                    const render::Camera& camera, const render::Viewport& view,
                                    float px);
  // `chart_top`: where a comparison's separation chart begins under the plot.
  void draw_plane(const scene::Frame& f, const render::Viewport& column,
                  const render::Viewport& area, std::optional<int> chart_top, float px);
  // Under the plot: the projection's convention and a legend for its marks.
  // `ticks_top`: where the plot's tick labels start (the captions stay below
  // them); with a separation chart under the plot (`chart_top`), right under
  // the tick labels, else at the column's foot.
  void draw_plane_captions(render::DrawList& flat, const render::Viewport& column, float ticks_top,
                           std::optional<float> chart_top, float px, const glm::vec4& text,
                           bool any_exit, bool any_infinity);
  // Labels of one part of the picture, placed by place_labels and recorded.
  void add_placed_labels(render::DrawList& flat, const std::vector<LabelRequest>& requests,
                         const std::vector<glm::vec4>& colours, const std::vector<Box>& obstacles,
                         const Box& bounds);
  // A 2D list to the GPU, or to the flat sink where one is set.
  void draw_flat(const render::DrawList& list);
  void draw_info_window(const scene::Frame& f, const scene::FrameLayout& layout, float px);
  // The key of the drift colours, one wording at every width, and its text.
  static std::array<std::string, 3> drift_key();
  static std::string drift_key_text(const std::array<std::string, 3>& parts);
  // Where the overlay window goes and how large it is (from this frame's text).
  Box info_window_box(const scene::Frame& f, const scene::FrameLayout& layout, float px);

  render::GlContext& context_;
  PainterOptions options_;
  scene::PageLayout page_;
  std::unique_ptr<render::Renderer> renderer_;
  render::GpuMesh glass_, arrow_, marker_sphere_;
  std::optional<render::GpuMesh> box_;
  Eigen::Vector3f box_half_extents_ = Eigen::Vector3f::Zero();
  std::vector<std::vector<glm::vec3>> grid_;
  render::RgbaImage image_;
  int reserved_left_ = 0;
  PaintedAnnotations annotations_;
  std::optional<Box> floating_overlay_;
  std::function<void(const render::DrawList&)>
      flat_sink_;  // this frame's overlay window where it covers the 3D view
};

}  // namespace epviz::paint
