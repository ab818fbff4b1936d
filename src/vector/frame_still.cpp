#include "vector/frame_still.hpp"

#include <chrono>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/frame_names.hpp"
#include "io/temp_name.hpp"
#include "numerics/failure.hpp"
#include "paint/painter_common.hpp"
#include "vector/cairo_font.hpp"
#include "vector/cairo_page.hpp"
#include "vector/cairo_painter.hpp"
#include "vector/overlay_window.hpp"

namespace epviz::vector {
namespace {

namespace fs = std::filesystem;

// What the painter drew of a frame with its 2D lists handed over: the 3D
// view's pixels, the lists in drawing order and what it placed.
struct SplitFrame {
  render::RgbaImage raster;
  std::vector<render::DrawList> flat;
  paint::PaintedAnnotations annotations;
};

SplitFrame paint_split(paint::FramePainter& painter, const scene::Frame& frame) {
  SplitFrame out;
  painter.set_flat_sink([&](const render::DrawList& list) { out.flat.push_back(list); });
  // The sink goes whatever happens: the painter is shared with PNG frames.
  struct Unset {
    paint::FramePainter& p;
    ~Unset() { p.set_flat_sink({}); }
  } unset{painter};
  out.raster = painter.paint(frame);
  out.annotations = painter.annotations();
  return out;
}

// The part `r` of an RGBA image as a cairo image (opaque: the frame's
// background is), drawn at its place.
void paint_raster_part(cairo_t* cr, const render::RgbaImage& image, const scene::Rect& r) {
  cairo_surface_t* part = cairo_image_surface_create(CAIRO_FORMAT_RGB24, r.width, r.height);
  cairo_surface_flush(part);
  unsigned char* data = cairo_image_surface_get_data(part);
  const int stride = cairo_image_surface_get_stride(part);
  for (int y = 0; y < r.height; ++y) {
    auto* row = reinterpret_cast<std::uint32_t*>(data + std::ptrdiff_t(y) * stride);
    const std::uint8_t* from =
        image.pixels.data() +
        (std::size_t(r.y + y) * std::size_t(image.width) + std::size_t(r.x)) * 4;
    for (int x = 0; x < r.width; ++x, from += 4)
      row[x] = std::uint32_t(from[0]) << 16 | std::uint32_t(from[1]) << 8 | from[2];
  }
  cairo_surface_mark_dirty(part);
  cairo_set_source_surface(cr, part, r.x, r.y);
  cairo_rectangle(cr, r.x, r.y, r.width, r.height);
  cairo_fill(cr);
  cairo_surface_destroy(part);
}

}  // namespace

std::string frame_still_bytes(paint::FramePainter& painter, const scene::Frame& frame,
                              FigureFormat format, double pt_per_unit) {
  if (format == FigureFormat::png)
    throw std::invalid_argument("frame_still_bytes: PNG is painted with GL, not cairo");
  const SplitFrame split = paint_split(painter, frame);
  const int w = split.raster.width, h = split.raster.height;
  const scene::FrameLayout layout = paint::layout_for(frame, w, h);
  const CairoFont font(split.annotations.font_px);
  PageInfo page{w, h, frame.overlay.title, frame.overlay.title};
  page.pt_per_unit = pt_per_unit;
  return page_bytes(page, format, [&](cairo_t* cr) {
    const glm::vec4 background = paint::to_glm(frame.colours.background);
    cairo_set_source_rgb(cr, background.r, background.g, background.b);
    cairo_paint(cr);
    if (layout.view_3d) paint_raster_part(cr, split.raster, *layout.view_3d);
    for (const auto& list : split.flat) paint_shapes(cr, list);
    if (split.annotations.overlay_window)
      draw_overlay_window(cr, painter, frame, *split.annotations.overlay_window, font);
    // The renderer draws the lists' text after everything else.
    for (const auto& list : split.flat) paint_labels(cr, list, font);
  });
}

paint::FramesWritten write_frame_stills(paint::FrameDrawer& drawer, paint::FramePainter& painter,
                                        const io::FrameRange& range, const StillFiles& files,
                                        const io::ProgressOptions& progress_options) {
  paint::FramesWritten out;
  fs::create_directories(files.dir);
  // Temporaries of runs killed before they could clean up (SIGKILL).
  io::remove_stale_temporaries(files.dir);
  const int frame_count = drawer.source().plan().frames;
  const std::string extension = std::string(".") + figure_format_name(files.format);
  io::ProgressLine progress(range.count(), progress_options);
  const auto start = std::chrono::steady_clock::now();
  try {
    for (int i = range.first; i <= range.last; ++i) {
      const auto path =
          files.dir / io::frame_file_name(i, frame_count, files.name + "_", extension);
      io::write_file_atomically(
          path, frame_still_bytes(painter, drawer.frame(i), files.format, files.pt_per_unit));
      ++out.drawn;
      progress.advance();
    }
  } catch (const numerics::IntegrationError& e) {
    out.failure = e.failure();
  }
  progress.finish();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace epviz::vector
