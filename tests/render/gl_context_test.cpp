#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "render/gl.hpp"
#include "render/gl_context.hpp"
#include "render/render_test_support.hpp"

namespace {

using epviz::render::make_gl_context;

TEST(GlContext, OsMesaGivesACoreContextOfAtLeast33) {
    auto& context = epviz::testing::shared_gl_context();
    EXPECT_EQ(context.backend(), "osmesa");
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
        EXPECT_NE(message.find("allowed: osmesa"), std::string::npos) << message;
    }
    epviz::testing::shared_gl_context();  // restore the shared context as current
}

TEST(GlContext, NonPositiveSizeIsRejected) {
    EXPECT_THROW(make_gl_context("osmesa", 0, 10), std::invalid_argument);
}

TEST(GlContext, BackendComesFromTheEnvironment) {
    setenv("EPVIZ_GL", "egl", 1);
    EXPECT_EQ(epviz::render::gl_backend_from_environment(), "egl");
    unsetenv("EPVIZ_GL");
    EXPECT_EQ(epviz::render::gl_backend_from_environment(), "osmesa");
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
