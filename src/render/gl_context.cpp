#include "render/gl_context.hpp"

#include <cstdlib>
#include <stdexcept>

#include "render/gl.hpp"
#include "render/osmesa_context.hpp"

namespace epviz::render {

std::string GlContext::describe() const {
    auto text = [](GLenum name) {
        const auto* value = reinterpret_cast<const char*>(glGetString(name));
        return std::string(value != nullptr ? value : "?");
    };
    return text(GL_RENDERER) + ", OpenGL " + text(GL_VERSION);
}

std::vector<std::string> gl_backends() { return {"osmesa"}; }

std::string gl_backend_from_environment() {
    const char* value = std::getenv("EPVIZ_GL");
    if (value == nullptr || *value == '\0') return gl_backends().front();
    return value;
}

std::unique_ptr<GlContext> make_gl_context(std::string_view backend, int width, int height) {
    if (width <= 0 || height <= 0)
        throw std::invalid_argument("GL surface size must be positive, got " + std::to_string(width) +
                                    "x" + std::to_string(height));
    if (backend == "osmesa") return std::make_unique<OsMesaContext>(width, height);

    std::string allowed;
    for (const auto& name : gl_backends()) allowed += (allowed.empty() ? "" : ", ") + name;
    throw std::invalid_argument("unknown GL backend '" + std::string(backend) +
                                "' (from --gl or EPVIZ_GL); allowed: " + allowed);
}

}  // namespace epviz::render
