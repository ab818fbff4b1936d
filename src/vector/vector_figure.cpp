#include "vector/vector_figure.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>

#include <stdexcept>

#include "io/atomic_file.hpp"
#include "paint/figure_drawing.hpp"
#include "paint/figure_panels.hpp"
#include "vector/cairo_font.hpp"
#include "vector/cairo_painter.hpp"

namespace epviz::vector {
namespace {

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

const std::string& title_of(const chart::Figure& figure) {
  return std::visit([](const auto& spec) -> const std::string& { return spec.title; },
                    figure.content);
}

// The drawing (measured in `font`) as the file's bytes; `title` names it in
// a PDF's metadata and `name` in messages.
std::string drawing_bytes(const paint::FigureDrawing& drawing, const CairoFont& font,
                          FigureFormat format, const std::string& title, const std::string& name) {
  std::string bytes;
  cairo_surface_t* surface =
      format == FigureFormat::svg
          ? cairo_svg_surface_create_for_stream(append, &bytes, drawing.width, drawing.height)
          : cairo_pdf_surface_create_for_stream(append, &bytes, drawing.width, drawing.height);
  if (format == FigureFormat::svg) {
    // The picture's numbers are pixels: a browser shows the SVG at the PNG's size.
    cairo_svg_surface_set_document_unit(surface, CAIRO_SVG_UNIT_PX);
  } else {
    cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_TITLE, title.c_str());
    cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "epviz");
  }
  cairo_t* cr = cairo_create(surface);
  paint_drawing(cr, drawing, font);
  cairo_show_page(cr);
  const cairo_status_t drawn = cairo_status(cr);
  cairo_destroy(cr);
  cairo_surface_finish(surface);
  const cairo_status_t finished = cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  for (const cairo_status_t s : {drawn, finished})
    if (s != CAIRO_STATUS_SUCCESS)
      throw std::runtime_error(std::string("cairo could not draw the figure '") + name +
                               "': " + cairo_status_to_string(s));
  return bytes;
}

}  // namespace

std::string vector_figure_bytes(const chart::Figure& figure, FigureFormat format,
                                const paint::ChartOptions& options) {
  if (format == FigureFormat::png)
    throw std::invalid_argument("vector_figure_bytes: PNG is painted with GL, not cairo");
  const CairoFont font(paint::chart_font_px(options));
  const paint::FigureDrawing drawing = paint::draw_figure(figure, options, font.chart_font());
  return drawing_bytes(drawing, font, format, title_of(figure), figure.file_name);
}

void write_vector_panels(const std::filesystem::path& path,
                         const std::vector<chart::Figure>& panels, FigureFormat format,
                         const paint::ChartOptions& options, int gap) {
  if (format == FigureFormat::png)
    throw std::invalid_argument("write_vector_panels: PNG is painted with GL, not cairo");
  const CairoFont font(paint::chart_font_px(options));
  std::vector<paint::FigureDrawing> drawings;
  for (const auto& f : panels)
    drawings.push_back(paint::draw_figure(f, options, font.chart_font()));
  const std::string title = panels.empty() ? std::string() : title_of(panels.front());
  io::write_file_atomically(
      path, drawing_bytes(paint::side_by_side(drawings, gap), font, format, title, path.string()));
}

void write_vector_figure(const std::filesystem::path& path, const chart::Figure& figure,
                         FigureFormat format, const paint::ChartOptions& options) {
  io::write_file_atomically(path, vector_figure_bytes(figure, format, options));
}

}  // namespace epviz::vector
