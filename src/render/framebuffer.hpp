#pragma once
// Offscreen render target: a multisampled colour + depth framebuffer that the
// frame is drawn into (MSAA anti-aliases lines and mesh edges) and a plain
// single-sample framebuffer it is resolved into for readback.
#include "render/gl.hpp"
#include "render/image.hpp"

namespace epviz::render {

// How long this thread's last read_pixels_rgba took, in ms: from the moment
// GL had finished drawing (it waits for that first, untimed, so that drawing
// on a deferred rasteriser is not counted here) through the copy and the row
// flip. The live server reports it as a stage of its own.
double last_read_back_ms();

class OffscreenFramebuffer {
 public:
  // samples <= 1 disables multisampling; larger values are clamped to GL_MAX_SAMPLES.
  OffscreenFramebuffer(int width, int height, int samples);
  ~OffscreenFramebuffer();
  OffscreenFramebuffer(const OffscreenFramebuffer&) = delete;
  OffscreenFramebuffer& operator=(const OffscreenFramebuffer&) = delete;

  void resize(int width, int height);
  // Binds the framebuffer that drawing goes to and sets the full viewport.
  void bind_for_drawing() const;
  // Resolves the multisampled image (no-op without MSAA).
  void resolve() const;
  // Resolves and reads back; rows are flipped from GL's bottom-up order to top-down.
  RgbaImage read_pixels_rgba() const;
  // Same, into an existing image (reuses its allocation from frame to frame).
  void read_pixels_rgba(RgbaImage& image) const;

  int width() const { return width_; }
  int height() const { return height_; }
  int samples() const { return samples_; }

 private:
  void create();
  void destroy();

  int width_ = 0;
  int height_ = 0;
  int samples_ = 0;
  GLuint draw_fbo_ = 0;  // multisampled when samples_ > 1, else the resolve target itself
  GLuint draw_colour_ = 0;
  GLuint draw_depth_ = 0;
  GLuint resolve_fbo_ = 0;
  GLuint resolve_colour_ = 0;
};

}  // namespace epviz::render
