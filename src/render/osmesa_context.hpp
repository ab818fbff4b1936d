#pragma once
// OSMesa backend: Mesa's software rasteriser (llvmpipe) rendering into a buffer
// in our memory. libOSMesa.so.8 is opened with dlopen on first use. OSMesa was
// removed from Mesa 25.1; EGL (egl_context.hpp) is the way forward.
#include <cstdint>
#include <vector>

#include "render/gl_context.hpp"

namespace epviz::render {

class OsMesaContext final : public GlContext {
 public:
  // Asks for OpenGL 3.3 core with OSMesaCreateContextAttribs (Mesa answers
  // with the newest core version it has) and makes it current. Throws
  // GlUnavailable when libOSMesa is missing or refuses the context.
  OsMesaContext(int width, int height);
  ~OsMesaContext() override;
  OsMesaContext(const OsMesaContext&) = delete;
  OsMesaContext& operator=(const OsMesaContext&) = delete;

  void make_current() override;
  void resize(int width, int height) override;
  int width() const override { return width_; }
  int height() const override { return height_; }
  std::string_view backend() const override { return "osmesa"; }

 private:
  void* context_ = nullptr;  // OSMesaContext; opaque so that GL/osmesa.h (and GL/gl.h) stay out
  int width_ = 0;
  int height_ = 0;
  // The default framebuffer. Frames are drawn into FBOs, but OSMesa needs a
  // buffer to make the context current at all.
  std::vector<std::uint8_t> buffer_;
};

}  // namespace epviz::render
