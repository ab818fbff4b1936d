#include "paint/frame_painter.hpp"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "paint/cloud_drawing.hpp"
#include "paint/cloud_spread_chart.hpp"
#include "paint/comparison_painter.hpp"
#include "paint/figure_common.hpp"
#include "paint/painter_common.hpp"
#include "paint/section_panel_drawing.hpp"
#include "physics/notation.hpp"
#include "render/colour_map.hpp"
#include "render/font_text.hpp"
#include "render/imgui_context_scope.hpp"
#include "render/mesh_data.hpp"
#include "scene/layout.hpp"
#include "scene/theme.hpp"

namespace epviz::paint {
namespace {

using render::DrawList;
using render::TextAnchor;

ImVec4 to_imgui(const scene::Rgba& c) { return {c[0], c[1], c[2], c[3]}; }

}  // namespace

const scene::Theme& ink_for(const scene::Frame& f) {
  const scene::Theme& t = scene::theme(f.theme);
  if (scene::is_light(f.colours.background) == t.light) return t;
  return t.light ? scene::dark_theme() : scene::light_theme();
}

int overlay_lines_shown(const scene::OverlayText& o, int height) {
  return scene::overlay_lines_shown(int(o.lines.size()), height);
}

scene::FrameLayout layout_for(const scene::Frame& f, int width, int height, int reserved_left) {
  return scene::frame_layout(scene::layout_request(f, width, height, reserved_left));
}

scene::FrameLayout layout_for(const scene::Layers& layers, const scene::OverlayText& overlay,
                              int width, int height, int reserved_left) {
  scene::Frame f;
  f.layers = layers;
  f.overlay = overlay;
  return layout_for(f, width, height, reserved_left);
}

render::Camera camera_for(const scene::Frame& f, const render::Viewport& view) {
  // The unit sphere (and its pole labels) fits the narrower side of the view at
  // the frame's distance; a distance of 3.4 radii frames it with a small margin.
  const float aspect = view.aspect();
  return render::Camera::orbit(
      glm::vec3(0.0f), scene::camera_distance_for(f.camera.distance, aspect),
      float(f.camera.azimuth_deg), float(f.camera.elevation_deg), scene::kFovDegrees, aspect);
}

FramePainter::FramePainter(render::GlContext& context, int width, int height,
                           PainterOptions options, scene::PageLayout page)
    : context_(context), options_(options), page_(page) {
  context_.make_current();
  render::RendererOptions ro;
  ro.width = width;
  ro.height = height;
  ro.msaa_samples = options.msaa_samples;
  ro.overlay = true;
  ro.overlay_options.builtin_font = options.builtin_font;
  const int type_height = page.type_height_for(height);
  ro.overlay_options.font_size_px = scene::overlay_font_px(type_height);
  ro.overlay_options.ui_scale = scene::ui_scale(type_height);
  renderer_ = std::make_unique<render::Renderer>(context_, ro);
  glass_ = render::GpuMesh(render::make_uv_sphere(1.0f, 72, 36));
  arrow_ = render::GpuMesh(render::make_arrow(1.0f, 0.018f, 0.045f, 0.12f, 20));
  marker_sphere_ = render::GpuMesh(render::make_uv_sphere(1.0f, 20, 10));
  // 64 points per circle: the chords stay within 0.4 px of a 300 px sphere.
  grid_ = render::make_lat_long_grid(1.0f, 5, 12, 64);
}

FramePainter::~FramePainter() = default;

void FramePainter::resize(int width, int height) {
  context_.make_current();
  renderer_->resize(width, height);
}
int FramePainter::width() const { return renderer_->width(); }
int FramePainter::height() const { return renderer_->height(); }

void FramePainter::draw_body(DrawList& list, const scene::Frame& f, float px) {
  if (!box_ || !box_half_extents_.isApprox(f.body.half_extents)) {
    box_.emplace(render::make_box(to_glm(f.body.half_extents)));
    box_half_extents_ = f.body.half_extents;
  }
  const glm::mat4 rot = glm::mat4_cast(to_glm(f.body_rotation));
  const glm::vec3 com = to_glm(f.body.centre_of_mass);
  list.add_mesh(*box_, rot * glm::translate(glm::mat4(1.0f), com),
                {to_glm(f.colours.body), 0.35f, 40.0f, 0.0f});
  const scene::Theme& ink = ink_for(f);

  // Box edges, slightly darker than the faces, so the orientation reads even
  // where two faces are lit alike.
  const glm::vec3 h = to_glm(f.body.half_extents);
  const float dark = ink.body_edge_factor;
  const glm::vec4 edge{f.colours.body[0] * dark, f.colours.body[1] * dark, f.colours.body[2] * dark,
                       1.0f};
  auto corner = [&](int i) {
    const glm::vec3 c(i & 1 ? h.x : -h.x, i & 2 ? h.y : -h.y, i & 4 ? h.z : -h.z);
    return glm::vec3(rot * glm::vec4(com + c * 1.002f, 1.0f));
  };
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit)) list.add_line(corner(i), corner(i | bit), edge, 1.0f * px);

  // Principal axes from the fixed point (their labels, the fixed point and the
  // centre of mass are drawn over the view: draw_view_annotations).
  const float length = axis_length(f);
  for (int i = 0; i < 3; ++i) {
    glm::vec3 axis(0.0f);
    axis[i] = 1.0f;
    const glm::mat4 model =
        rot * render::rotation_from_z_to(axis) * glm::scale(glm::mat4(1.0f), glm::vec3(length));
    list.add_mesh(arrow_, model, {to_glm(ink.axes[i]), 0.3f, 32.0f, 0.0f});
  }
}

void FramePainter::draw_sphere(DrawList& list, const scene::Frame& f, const render::Camera& camera,
                               const render::Viewport& view, float px) const {
  const scene::Theme& ink = ink_for(f);
  // Unlit glass: it covers a third of the picture, and llvmpipe pays for every
  // pixel's lighting (about 6 ms a 720p frame); the rim term keeps its outline.
  render::Material glass{to_glm(f.colours.sphere), 0.0f, 60.0f, 1.4f, false};
  glass.lit = false;
  list.add_mesh(glass_, glm::mat4(1.0f), glass);
  const glm::vec4 grid = to_glm(ink.sphere_grid);
  for (const auto& line : grid_) list.add_polyline(line, grid, 1.0f * px);

  // Every run's trail, its dashes measured on screen.
  draw_trails_3d(list, f, ink, px, [&](const glm::vec3& p) {
    const auto at = render::project_to_pixel(camera, view, p);
    return at ? glm::vec2(*at) : glm::vec2(0.0f);
  });
  list.add_marker(
      {to_glm(f.current), to_glm(f.colours.marker), to_glm(ink.marker_edge), 5.0f * px, 1.3f * px});
  // The pole labels N and S are placed over the view (draw_view_annotations).
}

void FramePainter::draw_plane(const scene::Frame& f, const render::Viewport& column,
                              const render::Viewport& area, std::optional<int> chart_top,
                              float px) {
  const double e = f.plane_extent;
  const render::Panel2D plot(area, {-e, e, -e, e}, true);
  const scene::Theme& ink = ink_for(f);
  const render::PanelStyle style = column_panel_style(ink, px);
  DrawList flat;
  draw_axes_in_print(plot, flat, style);
  plot.draw_circle(flat, {0.0, 0.0}, 1.0, {style.text.r, style.text.g, style.text.b, 0.85f},
                   1.3f * px);

  // Every run's path and marks (paint/comparison_painter.hpp).
  const PlaneMarksDrawn marks = draw_paths_plane(flat, plot, f, ink, px);
  const bool any_exit = marks.any_exit, any_infinity = marks.any_infinity;
  if (f.cloud) draw_cloud_plane(flat, plot, *f.cloud, cloud_colour(f), px);  // the cloud
  std::vector<Box> obstacles;
  const float marker_r = 4.5f * px;
  if (f.plane_current) {
    const glm::dvec2 at(f.plane_current->x(), f.plane_current->y());
    plot.draw_marker(flat, at,
                     {{}, to_glm(f.colours.marker), to_glm(ink.marker_edge), marker_r, 1.2f * px});
    obstacles.push_back(box_around(plot.to_pixel(at), glm::vec2(2.0f * marker_r + 2.0f * px)));
  }

  // The title above the plot says whose coordinates these are; the caption
  // under it, how they are made. Beside a section panel the plane has half
  // the column.
  const float title_room = float(f.section ? column.width / 2 : column.width) - 8 * px;
  // Appended, not "literal" + string: GCC 12 warns of a bound it misreads there.
  const std::string of_gamma =
      std::string("Riccati plane (a, b) of ").append(physics::symbol::gamma);
  for (const std::string& title :
       {of_gamma + " (body axes)", of_gamma, std::string("(a, b) plane")})
    if (gui().text_size(title).x <= title_room) {
      plot.draw_text(flat, {0.0, e}, {{}, title, style.text, TextAnchor::bottom, {0, -6 * px}});
      break;
    }
  // The axis names inside the plot's edges, next to the axes' ends.
  const glm::vec2 a_at = plot.to_pixel({e, 0.0}), b_at = plot.to_pixel({0.0, e});
  const glm::vec2 a_size = gui().text_size("a"), b_size = gui().text_size("b");
  const Box a_box{a_at + glm::vec2(-3 * px - a_size.x, -2 * px - a_size.y),
                  a_at + glm::vec2(-3 * px, -2 * px)};
  const Box b_box{b_at + glm::vec2(4 * px, 2 * px), b_at + glm::vec2(4 * px, 2 * px) + b_size};
  flat.add_text({glm::vec3(a_box.min, 0), "a", style.text, TextAnchor::top_left});
  flat.add_text({glm::vec3(b_box.min, 0), "b", style.text, TextAnchor::top_left});
  obstacles.push_back(a_box);
  obstacles.push_back(b_box);
  // "equator" next to the unit circle, where the path's marker is not.
  {
    const glm::vec2 size = gui().text_size("equator");
    LabelRequest r{"equator", size, {}};
    for (double deg : {-90.0, -60.0, -120.0, -30.0, -150.0, 90.0, 60.0, 120.0}) {
      const double t = deg * M_PI / 180.0;
      const glm::vec2 on = plot.to_pixel({std::cos(t), std::sin(t)});
      const glm::vec2 out = on - plot.to_pixel({0.0, 0.0});
      r.top_lefts.push_back(on + glm::normalize(out) * (2.0f * px) +
                            glm::vec2(out.x < -1.0f  ? -size.x
                                      : out.x > 1.0f ? 0.0f
                                                     : -0.5f * size.x,
                                      out.y < -1.0f  ? -size.y
                                      : out.y > 1.0f ? 0.0f
                                                     : -0.5f * size.y));
    }
    const Box bounds{glm::vec2(area.x, area.y),
                     glm::vec2(area.x + area.width, area.y + area.height)};
    add_placed_labels(flat, {r}, {style.text}, obstacles, bounds);
  }
  // At the column's foot; in a comparison right under the tick labels, far
  // from the separation chart below, so that they read as the plane's.
  draw_plane_captions(flat, column, float(area.y + area.height) + style.tick_length,
                      chart_top ? std::optional<float>(float(*chart_top) - 2 * px) : std::nullopt,
                      px, style.text, any_exit, any_infinity);
  draw_flat(flat);
}

void FramePainter::draw_plane_captions(render::DrawList& flat, const render::Viewport& column,
                                       float ticks_top, std::optional<float> chart_top, float px,
                                       const glm::vec4& text, bool any_exit, bool any_infinity) {
  const float font = gui().label_font_px();
  const float centre = float(column.x + column.width / 2);
  const bool wide = column.width >= 360;
  // A legend for the marks that appear, at the column's bottom; above it the
  // projection's convention (docs/math.md (3.1): from the south pole, hence
  // the minus signs).
  std::string legend;
  if (any_exit) legend += "hollow: leaves, dot: re-enters";
  if (any_infinity) {
    if (!legend.empty()) legend += "   ";
    // Appended piece by piece: GCC 12 misreads a bound in string + "literal" here.
    legend.append(physics::symbol::infinity).append(": through the south pole");
  }
  // Each line only where it stays below the plot's tick labels (and above a chart).
  const float lowest_top = ticks_top + font + 4.0f;
  const int lines = (!legend.empty() && wide ? 1 : 0) + 1;
  float y = chart_top ? std::min(*chart_top, lowest_top + float(lines) * font * 1.25f)
                      : float(column.y + column.height) - 4 * px;
  if (!legend.empty() && wide && y - font >= lowest_top) {
    flat.add_text({{centre, y, 0}, legend, text, TextAnchor::bottom});
    y -= font * 1.25f;
  }
  const std::string projection(physics::symbol::riccati_projection);
  for (const std::string& convention : {"projected from the south pole: " + projection, projection})
    if (gui().text_size(convention).x <= float(column.width) - 8 * px && y - font >= lowest_top) {
      flat.add_text({{centre, y, 0}, convention, text, TextAnchor::bottom});
      break;
    }
}

render::ImGuiOverlay& FramePainter::gui() { return *renderer_->overlay(); }

float FramePainter::layout_scale() { return gui().framebuffer_scale(); }

namespace {
// The style's sizes the overlay window is measured with, in frame pixels
// (ImGui's are in its layout units, frame pixels / the overlay's
// framebuffer scale, which a live view drawn smaller sets).
struct StyleInPixels {
  StyleInPixels(const ImGuiStyle& style, float scale)
      : ItemSpacing(style.ItemSpacing.x * scale, style.ItemSpacing.y * scale),
        WindowPadding(style.WindowPadding.x * scale, style.WindowPadding.y * scale) {}
  ImVec2 ItemSpacing, WindowPadding;
};
}  // namespace

namespace {
// The drift readouts' traffic light explained: the range each colour stands
// for (scene::drift_level's thresholds), in one wording at every width. Only
// the thresholds: a word for them ("round-off", "ok") would claim more than
// the colour does, and the bare ranges fit the smallest window.
int exponent_of(double v) { return int(std::lround(std::log10(v))); }
using DriftKey = std::array<std::string, 3>;
void draw_drift_key(const scene::Theme& ink, const DriftKey& parts) {
  const scene::Rgba* colours[] = {&ink.drift_ok, &ink.drift_warn, &ink.drift_bad};
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (i) ImGui::SameLine(0.0f, 0.0f);
    ImGui::TextColored(to_imgui(*colours[i]), "%s", render::drawable_text(parts[i]).c_str());
  }
}
// The drift table's heading: of the one run, or of each run of a comparison
// (its rows are the runs).
const char* drift_heading(const scene::Frame& f) {
  return f.comparison ? "largest rel. drift" : "max rel. drift";
}
// The width of the drift table's names column: 12 characters of the bitmap
// font (as its "%-12s" was), or the widest name, or the heading on its row.
float drift_names_width(const render::ImGuiOverlay& gui, const scene::Frame& f) {
  // The heading with a space more: it and the first column's label read apart.
  float w = std::max(gui.text_size("xxxxxxxxxxxx").x,
                     gui.text_size(std::string(drift_heading(f)) + " ").x);
  for (const auto& d : f.overlay.drifts) w = std::max(w, gui.text_size(d.first).x);
  return w;
}
// Whether the frame has the drift at the integrator's steps for every row.
bool with_step_drifts(const scene::Frame& f) {
  return !f.overlay.drifts.empty() && f.overlay.step_drifts.size() == f.overlay.drifts.size();
}
// The widest drift value the table writes (print_scientific, one decimal).
constexpr const char* kWidestDrift = "0.0×10⁻⁰⁰ ";
}  // namespace

const char* FramePainter::drift_table_heading(const scene::Frame& f) { return drift_heading(f); }

std::vector<std::string> FramePainter::drift_table_columns(const scene::Frame& f) {
  // What each value column measures: the drift over the states drawn (between
  // the steps, interpolated), and where the run has it, at the steps.
  if (with_step_drifts(f)) return {"drawn", "at steps"};
  return {"drawn states"};
}

std::vector<std::string> FramePainter::drift_table_row(const scene::Frame& f, std::size_t row) {
  std::vector<std::string> values{print_scientific(f.overlay.drifts[row].second)};
  if (with_step_drifts(f)) values.push_back(print_scientific(f.overlay.step_drifts[row]));
  return values;
}

std::vector<FramePainter::DriftPiece> FramePainter::drift_line(const scene::Frame& f) {
  if (f.overlay.drifts.empty()) return {};
  // The worst row over the drawn states: a NaN is the worst there is.
  std::size_t worst = 0;
  for (std::size_t r = 1; r < f.overlay.drifts.size(); ++r) {
    const double v = f.overlay.drifts[r].second, w = f.overlay.drifts[worst].second;
    if (std::isnan(w)) break;
    if (std::isnan(v) || v > w) worst = r;
  }
  const double drawn = f.overlay.drifts[worst].second;
  // The integral's symbol only ("C₁", not "C₁ (energy)"): one line is short.
  const std::string& name = f.overlay.drifts[worst].first;
  std::vector<DriftPiece> line{{"drift " + name.substr(0, name.find(" (")) + " ", {}},
                               {print_scientific(drawn), drawn}};
  if (with_step_drifts(f)) {
    const double steps = f.overlay.step_drifts[worst];
    line.push_back({" drawn, ", {}});
    line.push_back({print_scientific(steps), steps});
    line.push_back({" steps", {}});
  } else {
    line.push_back({" drawn", {}});
  }
  return line;
}

float FramePainter::drift_table_column_width() {
  render::ImGuiContextScope scope(gui().context());
  return gui().text_size(kWidestDrift).x + ImGui::GetStyle().ItemSpacing.x * layout_scale();
}

float FramePainter::drift_table_values_x(const scene::Frame& f) {
  render::ImGuiContextScope scope(gui().context());
  return drift_names_width(gui(), f) + ImGui::GetStyle().ItemSpacing.x * layout_scale();
}

void FramePainter::draw_flat(const render::DrawList& list) {
  if (flat_sink_)
    flat_sink_(list);
  else
    renderer_->draw_2d(list);
}

std::string FramePainter::drift_key_text(const std::array<std::string, 3>& parts) {
  return parts[0] + parts[1] + parts[2];
}

std::array<std::string, 3> FramePainter::drift_key() {
  const std::string warn = power_of_ten(exponent_of(scene::kDriftWarnFrom)),
                    bad = power_of_ten(exponent_of(scene::kDriftBadFrom));
  return {"<" + warn, "  <" + bad, "  ≥" + bad};
}

Box FramePainter::info_window_box(const scene::Frame& f, const scene::FrameLayout& layout,
                                  float px) {
  const scene::Rect where = layout.overlay_area        ? *layout.overlay_area
                            : layout.overlay_in_column ? *layout.panel_column
                            : layout.view_3d           ? *layout.view_3d
                            : layout.panel_column      ? *layout.panel_column
                                                       : scene::Rect{0, 0, width(), height()};
  // The window's size is computed from this frame's text: ImGui's auto-fit
  // would use the previous frame's, which belongs to another job in a gallery.
  const int shown = overlay_lines_shown(f.overlay, height());
  render::ImGuiContextScope scope(gui().context());
  const StyleInPixels st(ImGui::GetStyle(), layout_scale());
  float text_w = gui().text_size(f.overlay.title).x;
  for (int i = 0; i < shown; ++i)
    text_w = std::max(text_w, gui().text_size(f.overlay.lines[std::size_t(i)]).x);
  const bool one_line = scene::overlay_drifts_in_one_line(height());
  if (!f.overlay.drifts.empty() && one_line) {
    std::string whole;
    for (const auto& piece : drift_line(f)) whole += piece.text;
    text_w = std::max(text_w, gui().text_size(whole).x);
  } else if (!f.overlay.drifts.empty()) {  // the names, then the value columns; the key
    const auto columns = drift_table_columns(f);
    float values_w = float(columns.size() - 1) * drift_table_column_width();
    values_w += std::max(gui().text_size(kWidestDrift).x, gui().text_size(columns.back()).x);
    text_w = std::max({text_w, drift_names_width(gui(), f) + st.ItemSpacing.x + values_w,
                       gui().text_size(drift_key_text(drift_key())).x});
  }
  // Title, lines, then the drifts' heading, their rows and the key of their colours.
  const int rows = 1 + shown +
                   (f.overlay.drifts.empty() ? 0
                    : one_line               ? 1
                                             : 2 + int(f.overlay.drifts.size()));
  const float h = 2 * st.WindowPadding.y +
                  float(rows) * (gui().label_font_px() + st.ItemSpacing.y) +
                  (f.overlay.drifts.empty() ? 0.0f : st.ItemSpacing.y + 1.0f);
  const glm::vec2 size(text_w + 2 * st.WindowPadding.x, h);
  // In the panel's column: anchored at its top right, so that a long title
  // grows to the left instead of being cut at the image's edge. Over the 3D
  // view: at its top left corner, away from the panel.
  const glm::vec2 top_left =
      layout.overlay_in_column && !layout.overlay_area
          ? glm::vec2(float(where.x + where.width) - 6 * px - size.x, float(where.y) + 6 * px)
          : glm::vec2(float(where.x) + 6 * px, float(where.y) + 6 * px);
  if (!layout.view_3d || layout.overlay_area) return {top_left, top_left + size};
  const scene::Rect& v = *layout.view_3d;
  const Box view_box{{float(v.x), float(v.y)}, {float(v.right()), float(v.bottom())}};
  // In the column unless a long text widens it into the 3D view: it then
  // floats there as in small pictures.
  if (layout.overlay_in_column && !Box{top_left, top_left + size}.intersects(view_box))
    return {top_left, top_left + size};
  return floating_window_box(f, v, size, px);
}

Box FramePainter::floating_window_box(const scene::Frame& f, const scene::Rect& where,
                                      glm::vec2 size, float px) {
  // Floating over the 3D view: at the view's left edge, as high as it can be
  // without covering a run's current point; above the trail's key and a
  // single run's horizon note at the bottom. Where no place is clear, the
  // one that covers least.
  const glm::vec2 top_left(float(where.x) + 6 * px, float(where.y) + 6 * px);
  const float line = gui().label_font_px() * 1.45f;
  const float lowest = std::max(
      top_left.y, float(where.y + where.height) - 6 * px - size.y -
                      float(2 + horizon_note_rows(f)) * std::max(line, horizon_note_line(px)));
  // A corner the job asks for (scene::OverlayPlace), whatever it covers.
  if (const scene::OverlayPlace place = f.page.overlay; scene::is_corner(place)) {
    const bool right =
        place == scene::OverlayPlace::top_right || place == scene::OverlayPlace::bottom_right;
    const bool bottom =
        place == scene::OverlayPlace::bottom_left || place == scene::OverlayPlace::bottom_right;
    const glm::vec2 at(
        right ? std::max(top_left.x, float(where.x + where.width) - 6 * px - size.x) : top_left.x,
        bottom ? lowest : top_left.y);
    return {at, at + size};
  }
  const render::Viewport view = to_viewport(where);
  const auto marks = run_mark_boxes(f, camera_for(f, view), view, px);
  auto covered = [&](glm::vec2 at) {
    float area = 0.0f;
    for (const Box& m : marks) area += Box{at, at + size}.overlap_area(m);
    return area;
  };
  // At the left edge only: the key of the marks holds the top right.
  glm::vec2 best = top_left;
  // A window wider than the view (tiny pictures) covers the column's titles
  // and labels wherever it goes lower: it keeps the top.
  if (size.x > float(where.width) - 12 * px) return {best, best + size};
  float least = covered(top_left);
  for (float y = top_left.y; y <= lowest && least > 0.0f; y += 2 * px)
    if (const float c = covered({top_left.x, y}); c < least) {
      least = c;
      best = {top_left.x, y};
    }
  return {best, best + size};
}

void FramePainter::draw_info_window(const scene::Frame& f, const scene::FrameLayout& layout,
                                    float px) {
  const scene::Theme& ink = ink_for(f);
  {
    const Box box = info_window_box(f, layout, px);
    const int shown = overlay_lines_shown(f.overlay, height());
    // ImGui lays out in frame pixels / layout_scale().
    const float s = layout_scale();
    ImGui::SetNextWindowSize(ImVec2(box.width() / s, box.height() / s), ImGuiCond_Always);
    ImGui::SetNextWindowPos(ImVec2(box.min.x / s, box.min.y / s), ImGuiCond_Always);
    // More see-through where it floats over the 3D view (small pictures).
    ImGui::SetNextWindowBgAlpha(layout.overlay_in_column || !layout.view_3d
                                    ? ink.overlay_alpha_in_column
                                    : ink.overlay_alpha_floating);
    // The window in the theme's colours (the overlay's ImGui context has ImGui's dark ones).
    const std::pair<ImGuiCol, const scene::Rgba*> window_colours[] = {
        {ImGuiCol_WindowBg, &ink.overlay_window},
        {ImGuiCol_Border, &ink.overlay_border},
        {ImGuiCol_Separator, &ink.overlay_border},
        {ImGuiCol_Text, &ink.overlay_text},
        {ImGuiCol_TextDisabled, &ink.overlay_heading}};
    for (const auto& [which, colour] : window_colours)
      ImGui::PushStyleColor(which, to_imgui(*colour));
    const int pushed = int(std::size(window_colours));
    ImGui::Begin("overlay", nullptr,
                 ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoTitleBar |
                     ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoScrollbar);
    // Every text as the font can draw it (symbols, or ASCII in the bitmap font).
    auto text = [](const std::string& t) {
      ImGui::TextUnformatted(render::drawable_text(t).c_str());
    };
    ImGui::PushStyleColor(ImGuiCol_Text, to_imgui(ink.title));
    text(f.overlay.title);
    ImGui::PopStyleColor();
    for (int i = 0; i < shown; ++i) text(f.overlay.lines[std::size_t(i)]);
    if (!f.overlay.drifts.empty() && scene::overlay_drifts_in_one_line(height())) {
      ImGui::Separator();
      bool first = true;
      for (const auto& piece : drift_line(f)) {
        if (!first) ImGui::SameLine(0.0f, 0.0f);
        first = false;
        const std::string drawn = render::drawable_text(piece.text);
        if (piece.drift)
          ImGui::TextColored(to_imgui(ink.drift_colour(*piece.drift)), "%s", drawn.c_str());
        else
          ImGui::TextDisabled("%s", drawn.c_str());
      }
    } else if (!f.overlay.drifts.empty()) {
      ImGui::Separator();
      // In frame pixels, given to ImGui in its layout units.
      const float values_x = ImGui::GetStyle().WindowPadding.x * s + drift_table_values_x(f);
      const float column_w = drift_table_column_width();
      // The heading, and over each value column what it measures.
      ImGui::TextDisabled("%s", drift_heading(f));
      const auto columns = drift_table_columns(f);
      for (std::size_t c = 0; c < columns.size(); ++c) {
        ImGui::SameLine((values_x + float(c) * column_w) / s);
        ImGui::TextDisabled("%s", columns[c].c_str());
      }
      for (std::size_t row = 0; row < f.overlay.drifts.size(); ++row) {
        text(f.overlay.drifts[row].first);
        const auto values = drift_table_row(f, row);
        for (std::size_t c = 0; c < values.size(); ++c) {
          // Traffic light (scene::drift_level) of the column's own value.
          const double v = c == 0 ? f.overlay.drifts[row].second : f.overlay.step_drifts[row];
          ImGui::SameLine((values_x + float(c) * column_w) / s);
          ImGui::TextColored(to_imgui(ink.drift_colour(v)), "%s",
                             render::drawable_text(values[c]).c_str());
        }
      }
      draw_drift_key(ink, drift_key());
    }
    ImGui::End();
    ImGui::PopStyleColor(pushed);
  }
}

const render::RgbaImage& FramePainter::paint(const scene::Frame& f,
                                             const std::function<void()>& extra_ui) {
  context_.make_current();
  const int w = renderer_->width(), h = renderer_->height();
  if (f.page.type_height != page_.type_height)
    throw std::logic_error("FramePainter: the frame's type size is not the painter's");
  // Line widths and marks scale with the type.
  const float px = std::max(1.0f, float(f.page.type_height_for(h)) / 360.0f);
  const scene::FrameLayout layout = layout_for(f, w, h, reserved_left_);
  annotations_ = {};
  annotations_.map_top = ink_for(f).trail_map_top;
  annotations_.font_px = gui().label_font_px();
  // The overlay floating over the 3D view (small pictures) is drawn over
  // everything: the view's labels keep out of it.
  floating_overlay_.reset();
  if (f.layers.overlay) annotations_.overlay_window = info_window_box(f, layout, px);
  // So does a window in the column that a long title widens into the view.
  if (annotations_.overlay_window && layout.view_3d) {
    const scene::Rect& v = *layout.view_3d;
    const Box view{{float(v.x), float(v.y)}, {float(v.right()), float(v.bottom())}};
    if (!layout.overlay_in_column || annotations_.overlay_window->intersects(view))
      floating_overlay_ = annotations_.overlay_window;
  }

  renderer_->begin_frame(to_glm(f.colours.background));
  if (layout.view_3d) {
    DrawList scene3d;
    const render::Viewport view = to_viewport(*layout.view_3d);
    const render::Camera camera = camera_for(f, view);
    if (f.layers.body) draw_body(scene3d, f, px);
    if (f.layers.sphere) draw_sphere(scene3d, f, camera, view, px);
    if (f.cloud && f.layers.sphere)  // the cloud
      draw_cloud_sphere(scene3d, *f.cloud, cloud_colour(f), camera, view, px);
    renderer_->draw_3d(scene3d, camera, view);
    draw_view_annotations(f, camera, view, px);
    if (DrawList chart; f.cloud && f.layers.overlay) {  // the cloud's spread
      // Its text measured in the font it is drawn with.
      draw_cloud_spread_chart(chart, view, *f.cloud, cloud_colour(f), ink_for(f), px,
                              [&](const std::string& text) { return gui().text_size(text); });
      draw_flat(chart);
    }
  }
  if (layout.panel_column && f.layers.riccati)
    draw_plane(f, to_viewport(*layout.panel_column), to_viewport(*layout.plot_area),
               layout.chart_area ? std::optional<int>(layout.chart_area->y) : std::nullopt, px);
  if (layout.section_area && f.section) {
    DrawList section;
    draw_section_panel(section, *f.section, to_viewport(*layout.section_area), ink_for(f), px,
                       [&](const std::string& text) { return gui().text_size(text); });
    draw_flat(section);
  }
  {
    DrawList notes;
    const auto drawn = draw_run_annotations(
        notes, f, layout, ink_for(f), px,
        [&](const std::string& text) { return gui().text_size(text); },
        layout.view_3d ? annotations_.legend_bottom : std::nullopt, glm::ivec2(w, h));
    for (const auto& d : drawn) annotations_.legend.push_back({d.text, d.box, {}});
    draw_flat(notes);
  }
  const bool info_window = f.layers.overlay && !flat_sink_;  // a vector still draws its own
  if (info_window || extra_ui)
    renderer_->draw_overlay([&] {
      if (info_window) draw_info_window(f, layout, px);
      if (extra_ui) extra_ui();
    });
  renderer_->finish_frame(image_);
  return image_;
}

}  // namespace epviz::paint
