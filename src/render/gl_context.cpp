#include "render/gl_context.hpp"

#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "io/bad_input.hpp"
#include "render/egl_context.hpp"
#include "render/gl.hpp"
#include "render/osmesa_context.hpp"

namespace epviz::render {
namespace {

bool g_verbose = false;

void say(const std::string& line) {
  if (g_verbose) std::fprintf(stderr, "epviz: %s\n", line.c_str());
}

// "egl (surfaceless)", "osmesa".
std::string chosen_name(const GlContext& context) {
  std::string name(context.backend());
  if (!context.platform().empty()) name += " (" + context.platform() + ")";
  return name;
}

std::string gl_string(GLenum name) {
  const auto* value = reinterpret_cast<const char*>(glGetString(name));
  return value != nullptr ? value : "?";
}

// EGL first: it reaches a GPU where there is one and is what Mesa keeps; OSMesa
// is the fallback for machines without libEGL's Mesa vendor library.
std::unique_ptr<GlContext> make_auto_context(int width, int height) {
  std::string failures;
  try {
    return std::make_unique<EglContext>(width, height);
  } catch (const GlUnavailable& e) {
    failures = std::string("egl: ") + e.what();
    say("GL backend egl passed over: " + std::string(e.what()));
  }
  try {
    return std::make_unique<OsMesaContext>(width, height);
  } catch (const GlUnavailable& e) {
    failures += std::string("; osmesa: ") + e.what();
  }
  throw GlUnavailable("no GL backend works here (" + failures + ")");
}

std::unique_ptr<GlContext> make_context(std::string_view backend, int width, int height) {
  if (width <= 0 || height <= 0)
    throw std::invalid_argument("GL surface size must be positive, got " + std::to_string(width) +
                                "x" + std::to_string(height));
  if (backend == "auto") return make_auto_context(width, height);
  if (backend == "egl") return std::make_unique<EglContext>(width, height);
  if (backend == "osmesa") return std::make_unique<OsMesaContext>(width, height);

  std::string allowed;
  for (const auto& name : gl_backends()) allowed += (allowed.empty() ? "" : ", ") + name;
  throw io::BadInput("unknown GL backend '" + std::string(backend) +
                     "' (from --gl or EPVIZ_GL); allowed: " + allowed);
}

}  // namespace

std::string GlContext::renderer() const { return gl_string(GL_RENDERER); }
std::string GlContext::version() const { return gl_string(GL_VERSION); }
std::string GlContext::describe() const { return renderer() + ", OpenGL " + version(); }

std::vector<std::string> gl_backends() { return {"auto", "egl", "osmesa"}; }

std::string gl_backend_from_environment() {
  const char* value = std::getenv("EPVIZ_GL");
  if (value == nullptr || *value == '\0') return "auto";
  return value;
}

void set_gl_verbose(bool on) { g_verbose = on; }

std::unique_ptr<GlContext> make_gl_context(std::string_view backend, int width, int height) {
  auto context = make_context(backend, width, height);
  if (g_verbose)
    say("GL backend " + chosen_name(*context) + " (asked for " + std::string(backend) +
        "): " + context->describe());
  return context;
}

std::string probe_gl_backend() {
  try {
    const auto context = make_gl_context("auto", 16, 16);
    return chosen_name(*context) + ": " + context->describe();
  } catch (const std::exception& e) {
    return std::string("none: ") + e.what();
  }
}

}  // namespace epviz::render
