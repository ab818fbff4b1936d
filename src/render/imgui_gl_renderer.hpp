#pragma once
// Draws ImDrawData with our own small GL 3.3 renderer. Debian's prebuilt
// OpenGL3 backend looks GL up through libGL/GLX and cannot find an OSMesa
// context; this one uses the GL we link, and keeps all GL code in src/render.
#include "render/gl.hpp"
#include "render/shader_program.hpp"

struct ImDrawData;

namespace epviz::render {

class ImGuiGlRenderer {
 public:
  // Uses the current ImGui context: builds its font atlas into a texture and
  // stores the texture id in it. Needs a current GL context.
  ImGuiGlRenderer();
  ~ImGuiGlRenderer();
  ImGuiGlRenderer(const ImGuiGlRenderer&) = delete;
  ImGuiGlRenderer& operator=(const ImGuiGlRenderer&) = delete;

  // Draws into the bound framebuffer of framebuffer_width x framebuffer_height
  // pixels; leaves blending on and depth testing off.
  void render(const ImDrawData& draw_data, int framebuffer_width, int framebuffer_height);

 private:
  ShaderProgram program_;
  GLuint vao_ = 0;
  GLuint vertex_buffer_ = 0;
  GLuint index_buffer_ = 0;
  GLuint font_texture_ = 0;
};

}  // namespace epviz::render
