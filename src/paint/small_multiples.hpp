#pragma once
// Small multiples: a chart's panels (chart::ChartSpec::panels) drawn as one
// figure, a grid of charts under the chart's title whose axes all span every
// panel's points, so that the panels compare at a glance. Each panel is an
// ordinary chart (draw_chart), moved into its cell. No GL here.
#include "paint/figure_drawing.hpp"

namespace epviz::paint {

// `spec.panels` must not be empty. The picture is options.width wide and as
// tall as its rows of panels need.
FigureDrawing draw_small_multiples(const ChartSpec& spec, const ChartOptions& options,
                                   const ChartFont& font);

}  // namespace epviz::paint
