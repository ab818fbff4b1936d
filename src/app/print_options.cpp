#include "app/print_options.hpp"

#include <algorithm>
#include <cmath>

namespace epviz::app {

void add_print_options(cli::Command command, io::PrintSizeText& text) {
  command.add_option("--figure-width", text.width,
                     "LENGTH: the figures' printed width, e.g. 85mm, 8.5cm, 3.5in or 241pt (1 "
                     "to 20 in): the PNG is that many inches at --dpi, the SVG/PDF page that "
                     "wide in points, the text --font-size (docs/figures.md)");
  command.add_option("--font-size", text.font,
                     "PT: with --figure-width, the text's size in points (5 to 24; default 8)");
  command.add_option("--dpi", text.dpi,
                     "N: with --figure-width, the PNG's pixels per inch, and the layout's units "
                     "in the SVG/PDF (72 to 1200; default 300)");
}

std::optional<io::PrintSize> print_size_over(const io::PrintSizeText& command_line,
                                             const io::PrintSizeText& file,
                                             const io::PrintSizeText& file_names) {
  io::PrintSizeText text, names{"--figure-width", "--font-size", "--dpi"};
  const auto pick = [](const std::string& given, const std::string& from_file,
                       const std::string& file_name, std::string& value, std::string& name) {
    value = given.empty() ? from_file : given;
    if (given.empty() && !from_file.empty()) name = file_name;
  };
  pick(command_line.width, file.width, file_names.width, text.width, names.width);
  pick(command_line.font, file.font, file_names.font, text.font, names.font);
  pick(command_line.dpi, file.dpi, file_names.dpi, text.dpi, names.dpi);
  return io::parse_print_size(text, names.width, names.font, names.dpi);
}

#ifdef EPVIZ_HAVE_RENDER
int panel_gap(int screen_gap, const std::optional<io::PrintSize>& print) {
  return print ? int(std::lround(print->font_units())) : screen_gap;
}

int panel_columns(int panels, const std::optional<io::PrintSize>& print, int gap) {
  if (!print || panels <= 1) return std::max(panels, 1);
  const double least = 24.0 * print->font_units();
  const int fit = int((print->width_units() + gap) / (least + gap));
  return std::clamp(fit, 1, panels);
}

paint::ChartOptions chart_options(const paint::ChartOptions& screen,
                                  const std::optional<io::PrintSize>& print, int panels, int gap) {
  if (!print) return screen;
  paint::ChartOptions o = screen;
  // The row of panels fits the width asked; the rounding leaves at most a
  // unit per panel (1/dpi inch) of it blank.
  panels = std::max(panels, 1);
  o.width = std::max(1, (print->width_units() - gap * (panels - 1)) / panels);
  o.height = int(std::lround(double(o.width) * screen.height / screen.width));
  o.builtin_font = false;
  o.font_px = print->font_units();
  o.page_pt_per_unit = print->pt_per_unit();
  o.thin_line = float(0.5 * print->units_per_pt());
  o.grid_rows_of_text = true;
  return o;
}
#endif

}  // namespace epviz::app
