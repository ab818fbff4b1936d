#include "render/osmesa_context.hpp"

#include "render/gl.hpp"

#include <GL/osmesa.h>

#include <stdexcept>
#include <string>

namespace epviz::render {

OsMesaContext::OsMesaContext(int width, int height) {
    const int attributes[] = {
        OSMESA_FORMAT,              OSMESA_RGBA,
        OSMESA_DEPTH_BITS,          24,
        OSMESA_STENCIL_BITS,        8,
        OSMESA_PROFILE,             OSMESA_CORE_PROFILE,
        OSMESA_CONTEXT_MAJOR_VERSION, 3,
        OSMESA_CONTEXT_MINOR_VERSION, 3,
        0,
    };
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (context_ == nullptr)
        throw std::runtime_error("OSMesa could not create an OpenGL 3.3 core context "
                                 "(is libOSMesa from Mesa >= 20 installed?)");
    try {
        resize(width, height);
    } catch (...) {
        OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
        throw;
    }
}

OsMesaContext::~OsMesaContext() {
    if (context_ != nullptr) OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
}

void OsMesaContext::make_current() {
    if (OSMesaMakeCurrent(static_cast<OSMesaContext>(context_), buffer_.data(), GL_UNSIGNED_BYTE,
                          width_, height_) == 0)
        throw std::runtime_error("OSMesaMakeCurrent failed for a " + std::to_string(width_) + "x" +
                                 std::to_string(height_) + " buffer");
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
