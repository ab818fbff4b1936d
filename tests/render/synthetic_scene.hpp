#pragma once
// A small scene that uses every drawing primitive of src/render: a lit opaque
// sphere with principal-axis arrows inside a translucent sphere with a
// latitude/longitude grid and a time-coloured trail, a 2D panel with the unit
// circle and the trail's stereographic projection, an ImGui window and labels.
// Used by the pixel tests, the snapshot test and the 720p timing run.
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "render/gpu_mesh.hpp"
#include "render/panel_2d.hpp"
#include "render/renderer.hpp"

namespace epviz::testing {

class SyntheticScene {
 public:
  static constexpr glm::vec4 background{0.06f, 0.07f, 0.09f, 1.0f};
  static constexpr glm::vec4 body_colour{0.95f, 0.55f, 0.20f, 1.0f};
  static constexpr glm::vec4 circle_colour{0.85f, 0.87f, 0.92f, 1.0f};
  static constexpr float body_radius = 0.45f;

  SyntheticScene();  // needs a current GL context (uploads meshes)

  // Draws the whole frame (begin_frame .. draw_overlay); call finish_frame() after.
  void draw(render::Renderer& renderer, bool with_overlay = true) const;

  // Layout and geometry the tests look at, for an image of width x height.
  static render::Viewport view_3d(int width, int height);
  static render::Camera camera(int width, int height);
  static render::Panel2D panel(int width, int height);
  // Trail point at parameter t in [0, 1] on the unit sphere, and its colour.
  static glm::vec3 trail_point(float t);
  static glm::vec4 trail_colour(float t);

 private:
  render::GpuMesh body_;
  render::GpuMesh arrow_;
  render::GpuMesh glass_;
  std::vector<std::vector<glm::vec3>> grid_;
};

}  // namespace epviz::testing
