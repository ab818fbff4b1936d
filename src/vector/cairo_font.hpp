#pragma once
// The labels' font for cairo: DejaVu Sans through cairo's toy font API (which
// fontconfig resolves to the file the GL overlay loads), sized and placed as
// ImGui sizes and places it, so that a figure's layout, measured with this
// font, matches the layout of its PNG.
//
// ImGui's "font size" is the height from the font's ascender to its
// descender; cairo's is the em. Advances are kept unhinted (fractional), as
// ImGui keeps them.
#include <string>

#include <cairo.h>

#include "paint/figure_common.hpp"

namespace epviz::vector {

class CairoFont {
 public:
  // `px`: the ImGui size (ascender to descender), as paint::chart_font_px gives it.
  explicit CairoFont(float px);
  ~CairoFont();
  CairoFont(const CairoFont&) = delete;
  CairoFont& operator=(const CairoFont&) = delete;

  // The font as the figure layouts measure it; refers to this object.
  paint::ChartFont chart_font() const;
  float px() const { return px_; }
  float width(const std::string& text) const;
  // From the top of a line of text to its baseline, as ImGui places glyphs.
  float baseline() const { return baseline_; }
  // Makes `cr` draw text in this font.
  void select(cairo_t* cr) const;

 private:
  float px_;
  double em_ = 0.0;
  float baseline_ = 0.0f;
  cairo_surface_t* surface_ = nullptr;  // a 1 x 1 surface to measure on
  cairo_t* cr_ = nullptr;
  cairo_font_options_t* options_ = nullptr;
};

}  // namespace epviz::vector
