#pragma once
// A figure's size on paper: its width and its text's size in points (1/72 in),
// and the resolution of what is raster in it. Every figure command takes it
// (`--figure-width 85mm --font-size 8`), and a job or section file has the
// same keys; the layouts then work in units of 1/dpi inch, so that a PNG and
// a PDF of one figure share one layout, and the vector page is scaled to
// points (vector/cairo_page.hpp).
#include <optional>
#include <string>

namespace epviz::io {

struct PrintSize {
  double width_pt = 0.0;  // the page's width
  double font_pt = 8.0;   // the body text's height
  double dpi = 300.0;     // units of the layout per inch (and a PNG's pixels)

  // Layout units per point, and the page's width and the font in those units.
  double units_per_pt() const { return dpi / 72.0; }
  int width_units() const;
  float font_units() const;
  // Points per layout unit: what the vector page scales by.
  double pt_per_unit() const { return 72.0 / dpi; }
};

// The accepted range of each value, checked by the parsers and named in their messages.
inline constexpr double kMinFigureWidthPt = 72.0;    // 1 in
inline constexpr double kMaxFigureWidthPt = 1440.0;  // 20 in
inline constexpr double kMinFontPt = 5.0;
inline constexpr double kMaxFontPt = 24.0;
inline constexpr double kMinDpi = 72.0;
inline constexpr double kMaxDpi = 1200.0;
// The most units (PNG pixels) a figure's width may come to: width x dpi.
inline constexpr int kMaxWidthUnits = 16384;

// "85mm", "8.5cm", "3.5in", "241pt" (a number and its unit, no space) in
// points, from 1 to 20 inches; anything else throws io::BadInput naming
// `option`, quoting the text and saying what is allowed.
double parse_length_pt(const std::string& option, const std::string& text);
// A font size in points ("8", "9.5"), from 5 to 24.
double parse_font_pt(const std::string& option, const std::string& text);
// Dots per inch ("300"), from 72 to 1200.
double parse_dpi(const std::string& option, const std::string& text);

// The three options as a command line gives them ("" where not given): none
// given is no print size (a screen figure); a font size or dpi without a
// width is refused naming --figure-width, and so is a width that comes to
// more than kMaxWidthUnits at the dpi (naming --dpi where one is given).
struct PrintSizeText {
  std::string width, font, dpi;
};
std::optional<PrintSize> parse_print_size(const PrintSizeText& text,
                                          const std::string& width_option = "--figure-width",
                                          const std::string& font_option = "--font-size",
                                          const std::string& dpi_option = "--dpi");

}  // namespace epviz::io
