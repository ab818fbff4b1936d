#pragma once
// Draws a cloud (scene/cloud.hpp): its members as points on the sphere and in
// the (a, b) panel, and a small chart of its spread over time in a corner of
// the 3D view. Plain positions in, draw lists out: no physics here.
#include <glm/vec4.hpp>

#include "render/camera.hpp"
#include "render/draw_list.hpp"
#include "render/panel_2d.hpp"
#include "scene/cloud.hpp"
#include "scene/frame.hpp"
#include "scene/theme.hpp"

namespace epviz::paint {

// The members' colour: the current point's, half transparent, so that a
// dense cloud reads darker where it is denser.
glm::vec4 cloud_colour(const scene::Frame& f);

// `px`: the picture's line-width scale (pixels per 360th of its height).
// The points are square dots (render::DrawList::add_dots, one vertex each:
// ten thousand round markers, through a geometry shader, cost llvmpipe
// several times more, and squares made of two triangles a third more).
void draw_cloud_sphere(render::DrawList& list, const scene::CloudFrame& cloud,
                       const glm::vec4& colour, const render::Camera& camera,
                       const render::Viewport& view, float px);
void draw_cloud_plane(render::DrawList& flat, const render::Panel2D& plot,
                      const scene::CloudFrame& cloud, const glm::vec4& colour, float px);
// The spread chart, at the bottom right of the view: paint/cloud_spread_chart.hpp.

}  // namespace epviz::paint
