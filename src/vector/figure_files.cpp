#include "vector/figure_files.hpp"

#include "io/png_writer.hpp"
#include "paint/figure_painter.hpp"
#include "render/gl_choice.hpp"
#include "vector/vector_figure.hpp"

namespace epviz::vector {

std::vector<std::filesystem::path> write_figures(const std::vector<chart::Figure>& figures,
                                                 const std::filesystem::path& dir,
                                                 FigureFormat format, const std::string& gl,
                                                 const paint::ChartOptions& options) {
  std::vector<std::filesystem::path> written;
  if (figures.empty()) return written;
  std::unique_ptr<render::GlContext> context;
  if (format == FigureFormat::png) context = render::GlChoice(gl).open();
  for (const auto& figure : figures) {
    const auto path = dir / figure_file_name(figure.file_name, format);
    if (context) {
      const auto image = paint::paint_figure(*context, figure, options);
      io::write_png_rgba(path, image.width, image.height, image.pixels);
    } else {
      write_vector_figure(path, figure, format, options);
    }
    written.push_back(path);
  }
  return written;
}

}  // namespace epviz::vector
