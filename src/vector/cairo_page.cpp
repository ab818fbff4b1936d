#include "vector/cairo_page.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>

#include <stdexcept>

namespace epviz::vector {
namespace {

cairo_status_t append(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace

std::string page_bytes(const PageInfo& page, FigureFormat format,
                       const std::function<void(cairo_t*)>& draw) {
  std::string bytes;
  const bool scaled = page.pt_per_unit != 1.0;
  const double width_pt = page.width * page.pt_per_unit, height_pt = page.height * page.pt_per_unit;
  cairo_surface_t* surface =
      format == FigureFormat::svg
          ? cairo_svg_surface_create_for_stream(append, &bytes, width_pt, height_pt)
          : cairo_pdf_surface_create_for_stream(append, &bytes, width_pt, height_pt);
  if (format == FigureFormat::svg) {
    // Unscaled, the picture's numbers are pixels: a browser shows the SVG at
    // the PNG's size. A printed size is in points, as the PDF's is.
    cairo_svg_surface_set_document_unit(surface, scaled ? CAIRO_SVG_UNIT_PT : CAIRO_SVG_UNIT_PX);
  } else {
    cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_TITLE, page.title.c_str());
    cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "epviz");
  }
  cairo_t* cr = cairo_create(surface);
  if (scaled) cairo_scale(cr, page.pt_per_unit, page.pt_per_unit);
  draw(cr);
  cairo_show_page(cr);
  const cairo_status_t drawn = cairo_status(cr);
  cairo_destroy(cr);
  cairo_surface_finish(surface);
  const cairo_status_t finished = cairo_surface_status(surface);
  cairo_surface_destroy(surface);
  for (const cairo_status_t s : {drawn, finished})
    if (s != CAIRO_STATUS_SUCCESS)
      throw std::runtime_error(std::string("cairo could not draw the figure '") + page.name +
                               "': " + cairo_status_to_string(s));
  return bytes;
}

}  // namespace epviz::vector
