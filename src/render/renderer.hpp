#pragma once
// Composes a frame: 3D views and 2D panels from DrawLists, then the ImGui
// overlay, into an anti-aliased offscreen framebuffer, then reads it back.
//
//   Renderer renderer(*context, {.width = 1280, .height = 720});
//   renderer.begin_frame(background);
//   renderer.draw_3d(scene, camera, viewport);     // any number of views
//   renderer.draw_2d(panel_list);                  // image-pixel coordinates
//   renderer.draw_overlay([] { ImGui::Begin(...); ... ImGui::End(); });
//   RgbaImage image = renderer.finish_frame();
#include <functional>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "render/camera.hpp"
#include "render/draw_list.hpp"
#include "render/framebuffer.hpp"
#include "render/gl_context.hpp"
#include "render/gui_overlay.hpp"
#include "render/shader_program.hpp"

namespace epviz::render {

// Lights in view space (x right, y up, towards the viewer +z), so a scene
// stays lit the same way whichever way the camera turns.
struct Lighting {
  glm::vec3 key_direction{-0.45f, 0.6f, 0.65f};  // from upper left, in front
  glm::vec3 key_colour{0.85f, 0.83f, 0.80f};
  glm::vec3 fill_direction{0.6f, -0.25f, 0.5f};  // lower right, weaker and cooler
  glm::vec3 fill_colour{0.22f, 0.25f, 0.30f};
  glm::vec3 sky_colour{0.20f, 0.21f, 0.24f};
  glm::vec3 ground_colour{0.08f, 0.08f, 0.09f};
};

struct RendererOptions {
  int width = 1280;
  int height = 720;
  int msaa_samples = 4;  // 0 or 1: none; clamped to what the GL supports
  bool overlay = true;   // create the ImGui overlay
  OverlayOptions overlay_options;
};

class Renderer {
 public:
  // `context` must be current and outlive the renderer. Frames are drawn into
  // their own framebuffer, so the context's surface size does not matter.
  Renderer(GlContext& context, const RendererOptions& options);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  void resize(int width, int height);
  int width() const { return framebuffer_.width(); }
  int height() const { return framebuffer_.height(); }
  int msaa_samples() const { return framebuffer_.samples(); }

  // Binds the frame and clears it to `background` (sRGB + alpha).
  void begin_frame(const glm::vec4& background);

  // Draws a 3D list seen by `camera` into `viewport` with depth testing:
  // opaque meshes, fills, lines and markers first (lines and markers write
  // depth only after all of them are drawn), then translucent meshes far to
  // near with depth writes off (each drawn back faces first), so a
  // translucent sphere over a trail tints only the part behind it. Labels are projected
  // now and drawn by the overlay.
  void draw_3d(const DrawList& list, const Camera& camera, const Viewport& viewport,
               const Lighting& lighting = {});
  // Draws a list whose coordinates are image pixels (x right, y down) without
  // depth testing: fills, then lines, then markers; clipped to `clip` if given.
  void draw_2d(const DrawList& list, const Viewport* clip = nullptr);
  // Runs the ImGui overlay (and the labels queued by draw_3d/draw_2d).
  void draw_overlay(const std::function<void()>& build_ui = {});
  // Draws queued labels if draw_overlay was not called, resolves and reads back.
  RgbaImage finish_frame();
  void finish_frame(RgbaImage& image);

  ImGuiOverlay* overlay() { return overlay_.get(); }
  GlContext& context() { return context_; }

 private:
  struct StreamBuffer {
    GLuint vao = 0;
    GLuint vertices = 0;
    GLuint indices = 0;
  };
  void set_gl_viewport(const Viewport& viewport) const;
  void draw_meshes(const DrawList& list, const Camera& camera, const Lighting& lighting,
                   bool translucent);
  void draw_triangles(const DrawList& list, const glm::mat4& view_projection);
  void draw_dots(const DrawList& list, const glm::mat4& view_projection);
  void draw_lines(const DrawList& list, const glm::mat4& view_projection,
                  const glm::vec2& viewport_size);
  void draw_markers(const DrawList& list, const glm::mat4& view_projection,
                    const glm::vec2& viewport_size);
  // Lines and markers are expanded in screen space by geometry shaders: binds
  // `program` with the uniforms both share and uploads scratch_vertices_.
  void begin_screen_space_pass(ShaderProgram& program, const StreamBuffer& buffer,
                               const glm::mat4& view_projection, const glm::vec2& viewport_size);
  void queue_label(const TextLabel& label, const glm::vec2& pixel);

  GlContext& context_;
  OffscreenFramebuffer framebuffer_;
  ShaderProgram mesh_program_;
  ShaderProgram line_program_;
  ShaderProgram marker_program_;
  ShaderProgram solid_program_;
  StreamBuffer lines_;
  StreamBuffer markers_;
  StreamBuffer triangles_;
  StreamBuffer dots_;
  std::unique_ptr<ImGuiOverlay> overlay_;
  // Labels of this frame: copies, because the lists may be gone before the overlay runs.
  std::vector<TextLabel> labels_;
  std::vector<glm::vec2> label_pixels_;
  bool overlay_drawn_ = false;
  float min_alpha_ = 0.01f;  // line and marker fragments below this alpha are discarded
  // Scratch space reused from frame to frame.
  std::vector<float> scratch_vertices_;
  std::vector<std::uint32_t> scratch_indices_;
};

}  // namespace epviz::render
