#include "render/draw_list.hpp"

namespace epviz::render {

void DrawList::add_mesh(const GpuMesh& mesh, const glm::mat4& model, const Material& material) {
  meshes_.push_back({&mesh, model, material});
}

void DrawList::add_polyline(std::span<const LineVertex> vertices, float width_px, bool closed) {
  if (vertices.size() < 2 || !(width_px > 0.0f)) return;
  polylines_.push_back({line_vertices_.size(), vertices.size(), width_px, closed});
  line_vertices_.insert(line_vertices_.end(), vertices.begin(), vertices.end());
}

void DrawList::add_polyline(std::span<const glm::vec3> points, const glm::vec4& colour,
                            float width_px, bool closed) {
  if (points.size() < 2 || !(width_px > 0.0f)) return;
  polylines_.push_back({line_vertices_.size(), points.size(), width_px, closed});
  for (const auto& p : points) line_vertices_.push_back({p, colour});
}

void DrawList::add_line(const glm::vec3& a, const glm::vec3& b, const glm::vec4& colour,
                        float width_px) {
  const LineVertex vertices[] = {{a, colour}, {b, colour}};
  add_polyline(vertices, width_px);
}

void DrawList::add_marker(const Marker& marker) { markers_.push_back(marker); }

void DrawList::add_triangles(std::span<const ColouredVertex> vertices) {
  triangles_.insert(triangles_.end(), vertices.begin(),
                    vertices.end() - static_cast<long>(vertices.size() % 3));
}

void DrawList::add_dots(std::span<const ColouredVertex> centres, float size_px) {
  if (centres.empty() || !(size_px > 0.0f)) return;
  dots_.push_back({dot_vertices_.size(), centres.size(), size_px});
  dot_vertices_.insert(dot_vertices_.end(), centres.begin(), centres.end());
}

void DrawList::add_rect(const glm::vec2& min, const glm::vec2& max, const glm::vec4& colour) {
  const ColouredVertex corners[] = {
      {{min.x, min.y, 0}, colour}, {{max.x, min.y, 0}, colour}, {{max.x, max.y, 0}, colour},
      {{min.x, min.y, 0}, colour}, {{max.x, max.y, 0}, colour}, {{min.x, max.y, 0}, colour},
  };
  add_triangles(corners);
}

void DrawList::add_text(TextLabel label) { labels_.push_back(std::move(label)); }

void DrawList::clear() {
  meshes_.clear();
  line_vertices_.clear();
  polylines_.clear();
  markers_.clear();
  triangles_.clear();
  dot_vertices_.clear();
  dots_.clear();
  labels_.clear();
}

}  // namespace epviz::render
