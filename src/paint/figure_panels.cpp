#include "paint/figure_panels.hpp"

#include <algorithm>

namespace epviz::paint {
namespace {

// A figure's 2D list moved by `d` pixels (figures hold no meshes).
render::DrawList moved(const render::DrawList& list, glm::vec2 d) {
  render::DrawList out;
  for (const auto& p : list.polylines()) {
    const auto first = list.line_vertices().begin() + std::ptrdiff_t(p.first);
    std::vector<render::LineVertex> vertices(first, first + std::ptrdiff_t(p.count));
    for (auto& v : vertices) v.position += glm::vec3(d, 0.0f);
    out.add_polyline(vertices, p.width_px, p.closed);
  }
  for (auto m : list.markers()) {
    m.position += glm::vec3(d, 0.0f);
    out.add_marker(m);
  }
  std::vector<render::ColouredVertex> triangles = list.triangles();
  for (auto& v : triangles) v.position += glm::vec3(d, 0.0f);
  if (!triangles.empty()) out.add_triangles(triangles);
  for (auto label : list.labels()) {
    label.position += glm::vec3(d, 0.0f);
    out.add_text(std::move(label));
  }
  return out;
}

}  // namespace

FigureDrawing side_by_side(const std::vector<FigureDrawing>& panels, int gap) {
  FigureDrawing all;
  int x = 0;
  for (const auto& panel : panels) {
    if (x > 0) x += gap;
    for (const auto& layer : panel.layers) {
      auto clip = layer.clip;
      if (clip) clip->x += x;
      all.layers.push_back({moved(layer.list, {float(x), 0.0f}), clip});
    }
    x += panel.width;
    all.height = std::max(all.height, panel.height);
  }
  all.width = x;
  return all;
}

FigureDrawing stacked(const std::vector<FigureDrawing>& rows, int gap) {
  FigureDrawing all;
  int y = 0;
  for (const auto& row : rows) {
    if (y > 0) y += gap;
    for (const auto& layer : row.layers) {
      auto clip = layer.clip;
      if (clip) clip->y += y;
      all.layers.push_back({moved(layer.list, {0.0f, float(y)}), clip});
    }
    y += row.height;
    all.width = std::max(all.width, row.width);
  }
  all.height = y;
  return all;
}

}  // namespace epviz::paint
