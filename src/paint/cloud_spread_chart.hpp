#pragma once
// The cloud's spread chart (declared for the frame painter in
// cloud_drawing.hpp): the share of the sphere the cloud covers against time,
// on one fixed log scale (0.1 % to 100 %) in every frame and every tile, its
// time axis shared by a gallery's tiles (scene::CloudFrame::chart_t_end), its
// caption on the chart's own panel rather than over the cloud.
#include <glm/common.hpp>
#include <glm/vec4.hpp>

#include "paint/small_chart_axes.hpp"
#include "render/draw_list.hpp"
#include "render/panel_2d.hpp"
#include "scene/cloud.hpp"
#include "scene/theme.hpp"

namespace epviz::paint {

// The vertical range, log10 of the fraction of the sphere: from well under
// one histogram cell (1/1152) to the whole sphere.
inline constexpr double kLogSpreadMin = -3.5, kLogSpreadMax = 0.0;

// Where the chart's parts went (image pixels), for tests and neighbours.
struct CloudSpreadBoxes {
  TextBox panel;    // the chart's opaque background, everything inside it
  TextBox plot;     // the curve's rectangle
  TextBox caption;  // the lines saying what is plotted and the value now
};

// The chart in the bottom right corner of `view`, its text measured with
// `measure`. Nothing drawn (empty boxes) without a spread to show.
CloudSpreadBoxes draw_cloud_spread_chart(render::DrawList& flat, const render::Viewport& view,
                                         const scene::CloudFrame& cloud, const glm::vec4& colour,
                                         const scene::Theme& ink, float px,
                                         const MeasureText& measure);

}  // namespace epviz::paint
