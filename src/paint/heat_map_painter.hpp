#pragma once
// Draws a chart::HeatMapSpec with the render toolkit: one cell per value,
// coloured by the perceptual colour map of the trails (render/colour_map.hpp),
// column and row labels (thinned when they would overlap), a colour bar with
// its range, a title. Cells without a value are grey and hatched.
#include "chart/heat_map_spec.hpp"
#include "paint/chart_painter.hpp"
#include "render/gl_context.hpp"
#include "render/image.hpp"

namespace epviz::paint {

using chart::HeatMapSpec;

// `context` must be current (any size). Options as for charts (size, font).
render::RgbaImage paint_heat_map(render::GlContext& context, const HeatMapSpec& spec,
                                 const ChartOptions& options = {});

}  // namespace epviz::paint
