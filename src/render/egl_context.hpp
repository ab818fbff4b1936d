#pragma once
// EGL backend: an OpenGL 3.3 core context with no surface at all (frames are
// drawn into framebuffer objects). On a machine with a GPU the EGL device
// platform reaches it without a display server; otherwise Mesa's surfaceless
// platform gives llvmpipe. libEGL.so.1 is opened with dlopen on first use.
#include <string>

#include "render/gl_context.hpp"

namespace epviz::render {

class EglContext final : public GlContext {
 public:
  // Tries the device platform (hardware devices only) and then the
  // surfaceless one; throws GlUnavailable when neither gives a context.
  EglContext(int width, int height);
  ~EglContext() override;
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  void make_current() override;
  void resize(int width, int height) override;
  int width() const override { return width_; }
  int height() const override { return height_; }
  std::string_view backend() const override { return "egl"; }
  std::string platform() const override { return platform_; }

 private:
  void* display_ = nullptr;  // EGLDisplay; opaque so that EGL headers stay out
  void* context_ = nullptr;  // EGLContext
  std::string platform_;
  int width_ = 0;
  int height_ = 0;
};

}  // namespace epviz::render
