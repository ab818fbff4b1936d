// The vector painter lays a figure out with cairo's measure of the labels'
// font, the GL painter with ImGui's: for the two files of a figure to agree,
// both must measure DejaVu Sans alike, Greek letters, sub- and superscripts
// included (ImGui measures a glyph its font atlas lacks as a '?').
#include <gtest/gtest.h>

#include <string>

#include "paint/figure_painter.hpp"
#include "render/gui_overlay.hpp"
#include "render/render_test_support.hpp"
#include "vector/cairo_font.hpp"

namespace epviz {
namespace {

TEST(CairoFont, MeasuresLabelsAsTheGlOverlayDoes) {
  epviz::testing::shared_gl_context();
  for (const float px : {13.0f, 20.0f, 30.0f}) {
    render::OverlayOptions o;
    o.font_size_px = px;
    o.light_style = true;
    const render::ImGuiOverlay overlay(o);
    const paint::ChartFont gl = paint::chart_font(overlay);
    const vector::CairoFont cairo(px);
    EXPECT_FLOAT_EQ(cairo.px(), gl.px);
    for (const std::string text :
         {"Work-precision: euler", "1e-13", "γ error", "|ΔΩ|² / Ω₃", "h·ω ≤ 10⁻³", "ΓΔΘΛΞΠΣΦΨΩ"})
      EXPECT_NEAR(cairo.width(text), gl.width(text), 0.02f * px) << text << " at " << px << " px";
    // The baseline as ImGui puts it: ascender 1901 of 2384 units (hhea) of DejaVu Sans.
    EXPECT_NEAR(cairo.baseline(), px * 1901.0f / 2384.0f + 1.0f, 1.0f) << px;
  }
}

}  // namespace
}  // namespace epviz
