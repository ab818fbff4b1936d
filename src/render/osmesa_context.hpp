#pragma once
// OSMesa backend: Mesa's software rasteriser (llvmpipe) rendering into a buffer
// in our memory. OSMesa was removed from Mesa 25.1; EGL surfaceless is the way
// forward and fits behind GlContext the same way.
#include <cstdint>
#include <vector>

#include "render/gl_context.hpp"

namespace epviz::render {

class OsMesaContext final : public GlContext {
public:
    // Asks for OpenGL 3.3 core with OSMesaCreateContextAttribs (Mesa answers
    // with the newest core version it has) and makes it current.
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
    void* context_ = nullptr;  // OSMesaContext; kept opaque so GL/osmesa.h stays out of headers
    int width_ = 0;
    int height_ = 0;
    // The default framebuffer. Frames are drawn into FBOs, but OSMesa needs a
    // buffer to make the context current at all.
    std::vector<std::uint8_t> buffer_;
};

}  // namespace epviz::render
