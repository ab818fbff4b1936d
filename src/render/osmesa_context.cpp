#include "render/osmesa_context.hpp"

#include <stdexcept>
#include <string>

#include "render/gl.hpp"
#include "render/shared_library.hpp"

namespace epviz::render {
namespace {

// The part of <GL/osmesa.h> used here (that header includes GL/gl.h, which
// clashes with glcorearb.h). Values from Mesa's osmesa.h.
constexpr int osmesa_format = 0x22;
constexpr int osmesa_rgba = 0x1908;  // GL_RGBA
constexpr int osmesa_depth_bits = 0x30;
constexpr int osmesa_stencil_bits = 0x31;
constexpr int osmesa_profile = 0x33;
constexpr int osmesa_core_profile = 0x34;
constexpr int osmesa_context_major_version = 0x36;
constexpr int osmesa_context_minor_version = 0x37;

struct OsMesaApi {
  using CreateContextAttribs = void* (*)(const int* attributes, void* share);
  using DestroyContext = void (*)(void* context);
  using MakeCurrent = unsigned char (*)(void* context, void* buffer, unsigned type, int width,
                                        int height);
  using GetProcAddress = void* (*)(const char* name);

  SharedLibrary library{"libOSMesa.so.8", "libosmesa6"};
  CreateContextAttribs create_context_attribs =
      library.required<CreateContextAttribs>("OSMesaCreateContextAttribs");
  DestroyContext destroy_context = library.required<DestroyContext>("OSMesaDestroyContext");
  MakeCurrent make_current = library.required<MakeCurrent>("OSMesaMakeCurrent");
  GetProcAddress get_proc_address = library.required<GetProcAddress>("OSMesaGetProcAddress");
};

// Loaded on first use; a failed load is retried (and reported) each time.
const OsMesaApi& osmesa() {
  static const OsMesaApi api;
  return api;
}

void* osmesa_proc(const char* name) { return osmesa().get_proc_address(name); }

}  // namespace

OsMesaContext::OsMesaContext(int width, int height) {
  const int attributes[] = {
      osmesa_format,
      osmesa_rgba,
      osmesa_depth_bits,
      24,
      osmesa_stencil_bits,
      8,
      osmesa_profile,
      osmesa_core_profile,
      osmesa_context_major_version,
      3,
      osmesa_context_minor_version,
      3,
      0,
  };
  context_ = osmesa().create_context_attribs(attributes, nullptr);
  if (context_ == nullptr)
    throw GlUnavailable(
        "OSMesa could not create an OpenGL 3.3 core context "
        "(is libOSMesa from Mesa >= 20 installed?)");
  try {
    resize(width, height);
  } catch (...) {
    osmesa().destroy_context(context_);
    throw;
  }
}

OsMesaContext::~OsMesaContext() {
  if (context_ != nullptr) osmesa().destroy_context(context_);
}

void OsMesaContext::make_current() {
  if (osmesa().make_current(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_) == 0)
    throw std::runtime_error("OSMesaMakeCurrent failed for a " + std::to_string(width_) + "x" +
                             std::to_string(height_) + " buffer");
  load_gl_functions("osmesa", osmesa_proc);
}

void OsMesaContext::resize(int width, int height) {
  if (width <= 0 || height <= 0)
    throw std::invalid_argument("GL surface size must be positive, got " + std::to_string(width) +
                                "x" + std::to_string(height));
  buffer_.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0);
  width_ = width;
  height_ = height;
  make_current();
}

}  // namespace epviz::render
