#include "vector/raster_layer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "vector/cairo_painter.hpp"

namespace epviz::vector {
namespace {

struct Pixels {
  unsigned char* data;
  int width, height, stride;
};

std::uint32_t channel(float v) { return std::uint32_t(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); }

// A colour in 8-bit channels, straight alpha.
struct Colour8 {
  std::uint32_t r, g, b, a;
};
Colour8 colour8(const glm::vec4& c) {
  return {channel(c.r), channel(c.g), channel(c.b), channel(c.a)};
}

// `c` with coverage `cover` (0..255) "over" the premultiplied pixel `p`.
std::uint32_t over(std::uint32_t p, const Colour8& c, std::uint32_t cover) {
  const std::uint32_t a = (c.a * cover + 127) / 255, keep = 255 - a;
  const auto mix = [&](int shift, std::uint32_t v) {
    return ((v * a + ((p >> shift) & 0xffu) * keep + 127) / 255) << shift;
  };
  return mix(24, 255) | mix(16, c.r) | mix(8, c.g) | mix(0, c.b);
}

// One marker "over" the image (premultiplied ARGB32, as cairo keeps it), in
// image pixels: the colour of marker.frag at each pixel's centre. Pixels
// wholly inside an opaque fill are set without blending.
void stamp(const Pixels& img, const render::Marker& m, glm::vec2 centre, float scale) {
  const float r = m.radius_px * scale, w = m.outline_px * scale;
  const float reach = r + 0.5f;                       // outer edge of the fade
  const float solid = (w > 0.0f ? r - w : r) - 0.5f;  // inner edge of the fill's fade
  const Colour8 fill = colour8(m.fill);
  const std::uint32_t opaque_fill =
      fill.a == 255 ? 0xff000000u | fill.r << 16 | fill.g << 8 | fill.b : 0u;
  const int y0 = std::max(0, int(std::floor(centre.y - reach)));
  const int y1 = std::min(img.height - 1, int(std::ceil(centre.y + reach)));
  for (int y = y0; y <= y1; ++y) {
    const float dy = float(y) + 0.5f - centre.y;
    if (dy * dy >= reach * reach) continue;
    const float half = std::sqrt(reach * reach - dy * dy);
    const int x0 = std::max(0, int(std::floor(centre.x - half)));
    const int x1 = std::min(img.width - 1, int(std::ceil(centre.x + half)));
    auto* row = reinterpret_cast<std::uint32_t*>(img.data + std::ptrdiff_t(y) * img.stride);
    for (int x = x0; x <= x1; ++x) {
      const float dx = float(x) + 0.5f - centre.x, d2 = dx * dx + dy * dy;
      if (d2 >= reach * reach) continue;
      if (opaque_fill != 0u && solid > 0.0f && d2 <= solid * solid) {
        row[x] = opaque_fill;
        continue;
      }
      const float d = std::sqrt(d2);
      const float outer = std::clamp(reach - d, 0.0f, 1.0f);
      const float inner = w > 0.0f ? std::clamp(r - w + 0.5f - d, 0.0f, 1.0f) : 1.0f;
      const Colour8 c = inner >= 1.0f ? fill : colour8(m.outline + (m.fill - m.outline) * inner);
      row[x] = over(row[x], c, channel(outer));
    }
  }
}

void check(cairo_surface_t* image) {
  if (const cairo_status_t status = cairo_surface_status(image); status != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(image);
    throw std::runtime_error(std::string("cairo: cannot draw a dense layer as an image: ") +
                             cairo_status_to_string(status));
  }
}

}  // namespace

bool drawn_as_image(const render::DrawList& list) {
  return list.markers().size() + list.triangles().size() / 3 + list.dot_vertices().size() +
             list.polylines().size() >
         kMaxVectorShapes;
}

void paint_as_image(cairo_t* cr, const render::DrawList& list, const render::Viewport& box) {
  if (box.width <= 0 || box.height <= 0) return;
  cairo_surface_t* image = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, box.width * kRasterScale,
                                                      box.height * kRasterScale);
  check(image);
  cairo_t* ic = cairo_create(image);
  cairo_scale(ic, kRasterScale, kRasterScale);
  cairo_translate(ic, -box.x, -box.y);
  paint_fills_and_lines(ic, list);  // in paint_shapes' order: markers last
  cairo_destroy(ic);
  cairo_surface_flush(image);
  check(image);
  const Pixels pixels{cairo_image_surface_get_data(image), cairo_image_surface_get_width(image),
                      cairo_image_surface_get_height(image), cairo_image_surface_get_stride(image)};
  const float scale = float(kRasterScale);
  for (const auto& m : list.markers())
    stamp(pixels, m, (glm::vec2(m.position) - glm::vec2(box.x, box.y)) * scale, scale);
  cairo_surface_mark_dirty(image);
  cairo_save(cr);
  cairo_translate(cr, box.x, box.y);
  cairo_scale(cr, 1.0 / kRasterScale, 1.0 / kRasterScale);
  cairo_set_source_surface(cr, image, 0.0, 0.0);
  cairo_paint(cr);
  cairo_restore(cr);
  cairo_surface_destroy(image);
}

}  // namespace epviz::vector
