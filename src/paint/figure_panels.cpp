#include "paint/figure_panels.hpp"

#include <algorithm>

#include <glm/vec2.hpp>

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

// The drawings placed one after the other with `gap` pixels between them:
// left to right (`across`) with their tops aligned, or top to bottom with
// their left edges aligned.
FigureDrawing placed(const std::vector<FigureDrawing>& parts, int gap, bool across) {
  FigureDrawing all;
  int at = 0;
  for (const auto& part : parts) {
    if (at > 0) at += gap;
    const glm::ivec2 d = across ? glm::ivec2(at, 0) : glm::ivec2(0, at);
    for (const auto& layer : part.layers) {
      auto clip = layer.clip;
      if (clip) {
        clip->x += d.x;
        clip->y += d.y;
      }
      all.layers.push_back({moved(layer.list, glm::vec2(d)), clip});
    }
    at += across ? part.width : part.height;
    if (across)
      all.height = std::max(all.height, part.height);
    else
      all.width = std::max(all.width, part.width);
  }
  (across ? all.width : all.height) = at;
  return all;
}

}  // namespace

FigureDrawing side_by_side(const std::vector<FigureDrawing>& panels, int gap) {
  return placed(panels, gap, true);
}

FigureDrawing stacked(const std::vector<FigureDrawing>& rows, int gap) {
  return placed(rows, gap, false);
}

FigureDrawing panel_grid(const std::vector<FigureDrawing>& panels, int columns, int gap) {
  if (columns < 1 || std::size_t(columns) >= panels.size()) return side_by_side(panels, gap);
  std::vector<FigureDrawing> rows;
  for (std::size_t first = 0; first < panels.size(); first += std::size_t(columns)) {
    const auto end = panels.begin() + std::ptrdiff_t(std::min(panels.size(), first + columns));
    rows.push_back(side_by_side({panels.begin() + std::ptrdiff_t(first), end}, gap));
  }
  return stacked(rows, gap);
}

}  // namespace epviz::paint
