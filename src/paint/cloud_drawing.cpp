#include "paint/cloud_drawing.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/mat4x4.hpp>

#include "paint/figure_common.hpp"

namespace epviz::paint {

glm::vec4 cloud_colour(const scene::Frame& f) {
  const auto& c = f.colours.marker;
  return {c[0], c[1], c[2], 0.5f};
}

void draw_cloud_sphere(render::DrawList& list, const scene::CloudFrame& cloud,
                       const glm::vec4& colour, const render::Camera& camera,
                       const render::Viewport& view, float px) {
  if (cloud.sphere.empty() || view.height <= 0) return;
  const glm::mat4& v = camera.view;
  std::vector<render::ColouredVertex> dots;
  dots.reserve(cloud.sphere.size());
  for (const auto& p : cloud.sphere) {
    // A little inside the sphere: the dots write depth, and the trail and
    // the current point on the near side must stay in front of them.
    const glm::vec3 at = 0.997f * glm::vec3(p.x(), p.y(), p.z());
    if (-(v * glm::vec4(at, 1.0f)).z <= 0.0f) continue;  // behind the eye
    dots.push_back({at, colour});
  }
  list.add_dots(dots, 2.0f * px);
}

void draw_cloud_plane(render::DrawList& flat, const render::Panel2D& plot,
                      const scene::CloudFrame& cloud, const glm::vec4& colour, float px) {
  std::vector<render::ColouredVertex> dots;
  dots.reserve(cloud.plane.size());
  for (const auto& p : cloud.plane)
    dots.push_back({glm::vec3(plot.to_pixel({p.x(), p.y()}), 0.0f), colour});
  flat.add_dots(dots, 1.6f * px);
}

}  // namespace epviz::paint
