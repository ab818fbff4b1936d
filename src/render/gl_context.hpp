#pragma once
// The offscreen GL context behind a small interface, so that a second backend
// (EGL surfaceless, the successor of OSMesa) can join without touching callers.
// Chosen by a CLI flag or the EPVIZ_GL environment variable, like MuJoCo's
// MUJOCO_GL.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace epviz::render {

class GlContext {
public:
    virtual ~GlContext() = default;
    // Makes this context current on the calling thread.
    virtual void make_current() = 0;
    // Changes the size of the default surface; makes the context current.
    virtual void resize(int width, int height) = 0;
    virtual int width() const = 0;
    virtual int height() const = 0;
    // "osmesa", ...: the name make_gl_context() accepts for this backend.
    virtual std::string_view backend() const = 0;
    // GL_RENDERER and GL_VERSION, for logs and bug reports.
    std::string describe() const;
};

// The backends make_gl_context() accepts, in order of preference.
std::vector<std::string> gl_backends();

// The backend named by the EPVIZ_GL environment variable, or the first of
// gl_backends() when it is unset or empty. Not validated here.
std::string gl_backend_from_environment();

// Creates a current context with an OpenGL 3.3 core profile (or newer) and a
// default surface of width x height. Throws std::invalid_argument naming the
// allowed backends for an unknown name, std::runtime_error when the backend
// fails to create the context.
std::unique_ptr<GlContext> make_gl_context(std::string_view backend, int width, int height);

}  // namespace epviz::render
