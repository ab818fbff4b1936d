#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <thread>

#include "render/gl.hpp"
#include "render/gl_context.hpp"
#include "render/render_test_support.hpp"

namespace {

using epviz::render::make_gl_context;

TEST(GlContext, GivesACoreContextOfAtLeast33) {
  auto& context = epviz::testing::shared_gl_context();
  const std::string asked = epviz::render::gl_backend_from_environment();
  EXPECT_EQ(context.backend(), asked == "auto" ? "egl" : asked)
      << "auto prefers EGL, installed wherever the tests run";
  GLint major = 0, minor = 0, profile = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_GE(major * 10 + minor, 33) << context.describe();
  EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT) << context.describe();
}

TEST(GlContext, UnknownBackendIsRejectedWithTheAllowedNames) {
  try {
    make_gl_context("glx", 32, 32);
    FAIL() << "an unknown backend must throw";
  } catch (const std::invalid_argument& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("'glx'"), std::string::npos) << message;
    EXPECT_NE(message.find("allowed: auto, egl, osmesa"), std::string::npos) << message;
  }
  epviz::testing::shared_gl_context();  // restore the shared context as current
}

TEST(GlContext, NonPositiveSizeIsRejected) {
  EXPECT_THROW(make_gl_context("osmesa", 0, 10), std::invalid_argument);
}

TEST(GlContext, BackendComesFromTheEnvironment) {
  const char* before = std::getenv("EPVIZ_GL");
  const std::string saved = before != nullptr ? before : "";
  setenv("EPVIZ_GL", "osmesa", 1);
  EXPECT_EQ(epviz::render::gl_backend_from_environment(), "osmesa");
  unsetenv("EPVIZ_GL");
  EXPECT_EQ(epviz::render::gl_backend_from_environment(), "auto");
  if (before != nullptr) setenv("EPVIZ_GL", saved.c_str(), 1);
}

// Clears an 8x8 framebuffer object of the current context to (0.25, 0.5, 0.75)
// and reads one pixel back.
std::array<unsigned char, 4> cleared_pixel() {
  GLuint renderbuffer = 0, framebuffer = 0;
  glGenRenderbuffers(1, &renderbuffer);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 8, 8);
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, renderbuffer);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
  glViewport(0, 0, 8, 8);
  glClearColor(0.25f, 0.5f, 0.75f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  std::array<unsigned char, 4> pixel{};
  glReadPixels(3, 3, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteRenderbuffers(1, &renderbuffer);
  return pixel;
}

void expect_cleared_colour(const std::array<unsigned char, 4>& pixel, const std::string& where) {
  EXPECT_NEAR(pixel[0], 64, 1) << where;
  EXPECT_NEAR(pixel[1], 128, 1) << where;
  EXPECT_NEAR(pixel[2], 191, 1) << where;
}

// Both backends in one process: the function table follows the current
// context, and each gives the same pixels for the same clear.
TEST(GlContext, BothBackendsClearToTheSameColour) {
  for (const char* backend : {"egl", "osmesa"}) {
    auto context = make_gl_context(backend, 8, 8);
    EXPECT_EQ(context->backend(), backend);
    EXPECT_EQ(epviz::render::loaded_gl_functions_source(), backend);
    expect_cleared_colour(cleared_pixel(), backend);
  }
  epviz::testing::shared_gl_context();  // restore the shared context as current
}

// epviz serve makes its context on the render thread, not the main one.
TEST(GlContext, AContextMadeOnAnotherThreadDraws) {
  std::array<unsigned char, 4> pixel{};
  // An exception may not leave a thread (it would end the whole test
  // program): it is caught there and reported here.
  std::string error;
  std::thread worker([&] {
    try {
      auto context = make_gl_context(epviz::render::gl_backend_from_environment(), 8, 8);
      pixel = cleared_pixel();
    } catch (const std::exception& e) {
      error = e.what();
    } catch (...) {
      error = "an exception that is no std::exception";
    }
  });
  worker.join();
  ASSERT_EQ(error, "") << "on the worker thread";
  expect_cleared_colour(pixel, "worker thread");
  epviz::testing::shared_gl_context();
}

TEST(GlContext, ProbeNamesTheBackendAutoChooses) {
  const std::string probe = epviz::render::probe_gl_backend();
  EXPECT_EQ(probe.rfind("egl (", 0), 0u) << probe;  // EGL is installed wherever the tests run
  EXPECT_NE(probe.find("OpenGL"), std::string::npos) << probe;
  epviz::testing::shared_gl_context();
}

TEST(GlContext, ResizeKeepsTheContextUsable) {
  auto& context = epviz::testing::shared_gl_context();
  context.resize(80, 40);
  EXPECT_EQ(context.width(), 80);
  EXPECT_EQ(context.height(), 40);
  GLint viewport[4] = {};
  glGetIntegerv(GL_VIEWPORT, viewport);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  context.resize(64, 64);
}

}  // namespace
