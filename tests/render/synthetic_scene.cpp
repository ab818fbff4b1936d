#include "render/synthetic_scene.hpp"

#include <imgui.h>

#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

#include "render/colour_map.hpp"
#include "render/mesh_data.hpp"

namespace epviz::testing {
namespace {

constexpr int trail_points = 600;
constexpr float pi = std::numbers::pi_v<float>;

}  // namespace

SyntheticScene::SyntheticScene()
    : body_(render::make_uv_sphere(body_radius, 64, 32)),
      arrow_(render::make_arrow(0.85f, 0.022f, 0.055f, 0.16f, 24)),
      glass_(render::make_uv_sphere(1.0f, 96, 48)),
      grid_(render::make_lat_long_grid(1.0f, 5, 12, 144)) {}

render::Viewport SyntheticScene::view_3d(int width, int height) {
  return {0, 0, width * 5 / 8, height};
}

render::Camera SyntheticScene::camera(int width, int height) {
  // Far enough that the unit sphere and its pole labels fit the narrower side of the view.
  const float fov = 30.0f;
  const float aspect = view_3d(width, height).aspect();
  const float half = std::tan(glm::radians(fov) / 2.0f) * std::min(1.0f, aspect);
  return render::Camera::orbit(glm::vec3(0.0f), 1.22f / half, 35.0f, 22.0f, fov, aspect);
}

render::Panel2D SyntheticScene::panel(int width, int height) {
  const render::Viewport outer{width * 5 / 8, 0, width - width * 5 / 8, height};
  const int side = std::min(outer.width - outer.width / 4 - 8, outer.height - 60);
  const int left = outer.width / 4;
  // Low in the column: the ImGui window sits above it.
  const render::Viewport area{outer.x + left, height - side - height / 8, side, side};
  return render::Panel2D(area, {-1.3, 1.3, -1.3, 1.3}, true);
}

glm::vec3 SyntheticScene::trail_point(float t) {
  // A nutating precession: the polar angle wobbles while the azimuth turns.
  const float polar = (52.0f + 16.0f * std::sin(7.0f * 2.0f * pi * t)) * pi / 180.0f;
  const float azimuth = 1.6f * 2.0f * pi * t;
  return {std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
          std::cos(polar)};
}

glm::vec4 SyntheticScene::trail_colour(float t) {
  static const render::ColourMap map = render::ColourMap::time();
  return map(t, 0.35f + 0.65f * t);  // older parts fade
}

void SyntheticScene::draw(render::Renderer& renderer, bool with_overlay) const {
  using namespace render;
  const int width = renderer.width(), height = renderer.height();
  const float px = static_cast<float>(height) / 240.0f;  // line widths scale with the image

  renderer.begin_frame(background);

  DrawList scene;
  scene.add_mesh(body_, glm::mat4(1.0f), {body_colour, 0.45f, 40.0f, 0.0f});
  const glm::vec4 axis_colours[] = {
      {0.90f, 0.30f, 0.30f, 1}, {0.35f, 0.80f, 0.40f, 1}, {0.35f, 0.55f, 0.95f, 1}};
  const glm::vec3 axes[] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int i = 0; i < 3; ++i)
    scene.add_mesh(arrow_, rotation_from_z_to(axes[i]), {axis_colours[i], 0.3f, 32.0f, 0.0f});
  scene.add_mesh(glass_, glm::mat4(1.0f), {{0.55f, 0.70f, 0.95f, 0.10f}, 0.55f, 60.0f, 1.6f});
  for (const auto& line : grid_) scene.add_polyline(line, {0.75f, 0.82f, 0.95f, 0.16f}, 1.0f * px);

  std::vector<LineVertex> trail;
  std::vector<glm::dvec2> plane;
  std::vector<glm::vec4> plane_colours;
  for (int i = 0; i < trail_points; ++i) {
    const float t = static_cast<float>(i) / static_cast<float>(trail_points - 1);
    const glm::vec3 p = trail_point(t);
    trail.push_back({p, trail_colour(t)});
    // Stereographic projection from the south pole onto the equatorial plane.
    plane.emplace_back(p.x / (1.0f + p.z), p.y / (1.0f + p.z));
    plane_colours.push_back(trail_colour(t));
  }
  scene.add_polyline(trail, 2.5f * px);
  scene.add_marker({trail.back().position, trail_colour(1.0f), {1, 1, 1, 1}, 4.5f * px, 1.2f * px});
  scene.add_text({{0, 0, 1.13f}, "N", {0.92f, 0.94f, 1.0f, 1.0f}, TextAnchor::bottom});
  scene.add_text({{0, 0, -1.13f}, "S", {0.92f, 0.94f, 1.0f, 1.0f}, TextAnchor::top});
  renderer.draw_3d(scene, camera(width, height), view_3d(width, height));

  const Panel2D plot = panel(width, height);
  DrawList flat;
  PanelStyle style;
  style.tick_length = 3.0f * px;
  plot.draw_axes(flat, style);
  plot.draw_circle(flat, {0.0, 0.0}, 1.0, circle_colour, 1.5f * px);
  plot.draw_polyline(flat, plane, plane_colours, 1.8f * px);
  plot.draw_marker(flat, plane.back(),
                   {{}, trail_colour(1.0f), {1, 1, 1, 1}, 3.5f * px, 1.0f * px});
  plot.draw_text(flat, {0.0, 1.3},
                 {{}, "(a, b) plane", style.text, TextAnchor::bottom, {0.0f, -4.0f * px}});
  renderer.draw_2d(flat);

  if (with_overlay) {
    renderer.draw_overlay([width] {
      // Top right, above the panel: the sphere keeps the left side to itself.
      ImGui::SetNextWindowPos(ImVec2(static_cast<float>(width - 6), 6.0f), ImGuiCond_Always,
                              ImVec2(1.0f, 0.0f));
      ImGui::SetNextWindowBgAlpha(0.8f);
      ImGui::Begin("epviz", nullptr,
                   ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove |
                       ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoTitleBar);
      ImGui::TextUnformatted("epviz demo");
      ImGui::Text("t = %.2f", 12.5);
      ImGui::TextColored(ImVec4(0.55f, 0.85f, 0.55f, 1.0f), "dH 1.2e-12");
      ImGui::End();
    });
  }
}

}  // namespace epviz::testing
