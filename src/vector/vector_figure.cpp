#include "vector/vector_figure.hpp"

#include <stdexcept>

#include "io/atomic_file.hpp"
#include "paint/figure_drawing.hpp"
#include "paint/figure_panels.hpp"
#include "vector/cairo_font.hpp"
#include "vector/cairo_page.hpp"
#include "vector/cairo_painter.hpp"

namespace epviz::vector {
namespace {

const std::string& title_of(const chart::Figure& figure) {
  return std::visit([](const auto& spec) -> const std::string& { return spec.title; },
                    figure.content);
}

// The drawing (measured in `font`) as the file's bytes, `pt_per_unit`
// points a unit; `title` names it in a PDF's metadata and `name` in messages.
std::string drawing_bytes(const paint::FigureDrawing& drawing, const CairoFont& font,
                          FigureFormat format, double pt_per_unit, const std::string& title,
                          const std::string& name) {
  return page_bytes({.width = drawing.width,
                     .height = drawing.height,
                     .title = title,
                     .name = name,
                     .pt_per_unit = pt_per_unit},
                    format, [&](cairo_t* cr) { paint_drawing(cr, drawing, font); });
}

}  // namespace

std::string vector_figure_bytes(const chart::Figure& figure, FigureFormat format,
                                const paint::ChartOptions& options) {
  if (format == FigureFormat::png)
    throw std::invalid_argument("vector_figure_bytes: PNG is painted with GL, not cairo");
  const CairoFont font(paint::chart_font_px(options));
  const paint::FigureDrawing drawing = paint::draw_figure(figure, options, font.chart_font());
  return drawing_bytes(drawing, font, format, options.page_pt_per_unit, title_of(figure),
                       figure.file_name);
}

void write_vector_panels(const std::filesystem::path& path,
                         const std::vector<chart::Figure>& panels, FigureFormat format,
                         const paint::ChartOptions& options, int gap, int columns) {
  if (format == FigureFormat::png)
    throw std::invalid_argument("write_vector_panels: PNG is painted with GL, not cairo");
  const CairoFont font(paint::chart_font_px(options));
  std::vector<paint::FigureDrawing> drawings;
  for (const auto& f : panels)
    drawings.push_back(paint::draw_figure(f, options, font.chart_font()));
  const std::string title = panels.empty() ? std::string() : title_of(panels.front());
  io::write_file_atomically(path,
                            drawing_bytes(paint::panel_grid(drawings, columns, gap), font, format,
                                          options.page_pt_per_unit, title, path.string()));
}

void write_vector_figure(const std::filesystem::path& path, const chart::Figure& figure,
                         FigureFormat format, const paint::ChartOptions& options) {
  io::write_file_atomically(path, vector_figure_bytes(figure, format, options));
}

}  // namespace epviz::vector
