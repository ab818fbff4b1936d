#pragma once
// Shared helpers for the render tests: one GL context per test program
// (creating contexts is the slow part), and small pixel measures. The backend
// comes from EPVIZ_GL (CTest runs the GL test programs once per backend).
#include <cstdlib>
#include <memory>

#include <glm/vec4.hpp>

#include "render/gl_context.hpp"
#include "render/image.hpp"

namespace epviz::testing {

// A current context of the EPVIZ_GL backend shared by all tests of the program.
inline render::GlContext& shared_gl_context() {
  static std::unique_ptr<render::GlContext> context = [] {
    // Two rasteriser threads: the machine has two cores, and results must
    // not depend on it anyway.
    setenv("LP_NUM_THREADS", "2", 0);
    return render::make_gl_context(render::gl_backend_from_environment(), 64, 64);
  }();
  context->make_current();
  return *context;
}

inline glm::vec4 pixel_colour(const render::RgbaImage& image, int x, int y) {
  return glm::vec4(image.at(x, y)) / 255.0f;
}

inline float luminance(const glm::vec4& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

inline float max_channel_difference(const glm::vec4& a, const glm::vec4& b) {
  float d = 0.0f;
  for (int i = 0; i < 3; ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

}  // namespace epviz::testing
