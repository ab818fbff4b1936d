#pragma once
// The offscreen GL context behind a small interface: EGL (a GPU through the
// device platform, else Mesa's surfaceless platform) or OSMesa, each loaded
// with dlopen only when a context is made. Chosen by a CLI flag or the
// EPVIZ_GL environment variable, like MuJoCo's MUJOCO_GL.
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace epviz::render {

// A backend that cannot run here: its library is missing (the message names the
// Debian package to install) or it cannot create a 3.3 core context.
class GlUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class GlContext {
 public:
  virtual ~GlContext() = default;
  // Makes this context current on the calling thread.
  virtual void make_current() = 0;
  // Changes the size of the default surface; makes the context current.
  virtual void resize(int width, int height) = 0;
  virtual int width() const = 0;
  virtual int height() const = 0;
  // "egl" or "osmesa": the name make_gl_context() accepts for this backend.
  virtual std::string_view backend() const = 0;
  // How the backend reached the driver: "device" or "surfaceless" for EGL,
  // "" for OSMesa.
  virtual std::string platform() const { return {}; }
  // GL_RENDERER and GL_VERSION, for logs and bug reports.
  std::string renderer() const;
  std::string version() const;
  // "<renderer>, OpenGL <version>".
  std::string describe() const;
};

// The names make_gl_context() accepts: "auto" (EGL, then OSMesa), "egl", "osmesa".
std::vector<std::string> gl_backends();

// The backend named by the EPVIZ_GL environment variable, or "auto" when it is
// unset or empty. Not validated here.
std::string gl_backend_from_environment();

// Creates a current context with an OpenGL 3.3 core profile (or newer) and a
// default surface of width x height. Throws io::BadInput naming the allowed
// backends for an unknown name (commands refuse it earlier: gl_choice.hpp),
// GlUnavailable when the backend (for "auto": every backend) cannot create
// the context.
std::unique_ptr<GlContext> make_gl_context(std::string_view backend, int width, int height);

// When on, make_gl_context() says on stderr which backend it chose and why
// others were passed over (epviz --verbose).
void set_gl_verbose(bool on);

// What "auto" chooses on this machine, e.g. "egl (surfaceless): llvmpipe (LLVM
// 15.0.6, 256 bits), OpenGL 4.5 (Core Profile) Mesa 22.3.6", or "none: <why>".
// Creates and destroys a context, draws nothing.
std::string probe_gl_backend();

}  // namespace epviz::render
