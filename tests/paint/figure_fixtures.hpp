#pragma once
// What the figure painters' tests share: pictures in ImGui's built-in font
// (no dependence on the fonts a machine has) and a log-log chart of two series.
#include <cmath>

#include "paint/figure_common.hpp"
#include "paint/figure_painter.hpp"
#include "render/gui_overlay.hpp"
#include "render/render_test_support.hpp"

namespace epviz::testing {

inline paint::ChartOptions builtin_font_options(int width = 640, int height = 400) {
  return {.width = width, .height = height, .msaa_samples = 4, .builtin_font = true};
}

// The built-in font as the painters measure it: on the overlay that draws it.
inline const paint::ChartFont& builtin_chart_font() {
  shared_gl_context();  // the overlay needs a current context
  static const render::ImGuiOverlay overlay([] {
    render::OverlayOptions o;
    o.builtin_font = true;
    return o;
  }());
  static const paint::ChartFont font = paint::chart_font(overlay);
  return font;
}

// Two power laws on log-log axes, a work-precision chart's shape.
inline paint::ChartSpec two_series() {
  paint::ChartSpec s;
  s.title = "Work-precision (test)";
  s.x_label = "CPU time [ms]";
  s.y_label = "error";
  s.log_x = s.log_y = true;
  paint::ChartSeries a, b;
  a.name = "rk4";
  b.name = "gauss6";
  for (int i = 0; i < 6; ++i) {
    const double x = std::pow(10.0, -2.0 + 0.6 * i);
    a.points.push_back({x, 1e-2 * std::pow(x, -4.0) * 1e-6});
    b.points.push_back({x * 2.0, 1e-3 * std::pow(x, -6.0) * 1e-8});
  }
  s.series = {a, b};
  return s;
}

}  // namespace epviz::testing
