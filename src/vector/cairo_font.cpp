#include "vector/cairo_font.hpp"

#include <cairo-ft.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace epviz::vector {
namespace {

constexpr const char* kFamily = "DejaVu Sans";

// The family fontconfig found for kFamily: another one where DejaVu Sans is
// not installed, which would give figures another layout than their PNGs.
std::string resolved_family(cairo_t* cr) {
  cairo_scaled_font_t* font = cairo_get_scaled_font(cr);
  if (cairo_scaled_font_get_type(font) != CAIRO_FONT_TYPE_FT) return {};
  const FT_Face face = cairo_ft_scaled_font_lock_face(font);
  std::string family = face != nullptr && face->family_name != nullptr ? face->family_name : "";
  cairo_ft_scaled_font_unlock_face(font);
  return family;
}

}  // namespace

CairoFont::CairoFont(float px) : px_(px) {
  surface_ = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 1, 1);
  cr_ = cairo_create(surface_);
  options_ = cairo_font_options_create();
  // Unhinted outlines and fractional advances: the same widths on every
  // surface, and the widths ImGui measures.
  cairo_font_options_set_hint_style(options_, CAIRO_HINT_STYLE_NONE);
  cairo_font_options_set_hint_metrics(options_, CAIRO_HINT_METRICS_OFF);
  cairo_select_font_face(cr_, kFamily, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_options(cr_, options_);
  cairo_set_font_size(cr_, 1.0);
  cairo_font_extents_t unit;
  cairo_font_extents(cr_, &unit);
  if (cairo_status(cr_) != CAIRO_STATUS_SUCCESS || !(unit.ascent + unit.descent > 0.0) ||
      resolved_family(cr_) != kFamily) {
    cairo_destroy(cr_);
    cairo_surface_destroy(surface_);
    cairo_font_options_destroy(options_);
    throw std::runtime_error(
        "no font for the text in vector figures: fontconfig finds no DejaVu Sans; install the "
        "Debian package fonts-dejavu-core");
  }
  em_ = double(px) / (unit.ascent + unit.descent);
  cairo_set_font_size(cr_, em_);
  // ImGui puts the baseline one pixel below the ascender, rounded down.
  baseline_ = float(std::floor(unit.ascent * em_ + 1.0));
}

CairoFont::~CairoFont() {
  cairo_destroy(cr_);
  cairo_surface_destroy(surface_);
  cairo_font_options_destroy(options_);
}

float CairoFont::width(const std::string& text) const {
  if (text.empty()) return 0.0f;
  cairo_text_extents_t e;
  cairo_text_extents(cr_, text.c_str(), &e);
  return float(e.x_advance);
}

paint::ChartFont CairoFont::chart_font() const {
  return {px_, [this](const std::string& text) { return width(text); }};
}

void CairoFont::select(cairo_t* cr) const {
  cairo_select_font_face(cr, kFamily, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_options(cr, options_);
  cairo_set_font_size(cr, em_);
}

}  // namespace epviz::vector
