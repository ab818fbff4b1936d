#pragma once
// What to draw, as plain data: meshes with materials, thick polylines with
// per-vertex colour, round markers, filled triangles, square dots and text labels. A
// DrawList knows nothing about GL state; the Renderer draws it in an order
// that keeps translucency right (opaque first, translucent last).
#include <span>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace epviz::render {

class GpuMesh;

struct Material {
  glm::vec4 colour{0.8f, 0.8f, 0.8f,
                   1.0f};   // sRGB; alpha < 1 draws translucent, after everything opaque
  float specular = 0.35f;   // strength of the key light's highlight
  float shininess = 48.0f;  // Blinn exponent
  float rim = 0.0f;         // extra opacity at grazing angles (glass-like silhouettes)
  // Translucent only: also draw the inside of the far half (a second pass;
  // switch off to halve the cost of a large translucent sphere).
  bool back_faces = true;
  // Unlit: the colour as it is, with only the rim term (cheap on llvmpipe,
  // where per-pixel lighting of a large translucent shell dominates a frame).
  bool lit = true;
};

struct LineVertex {
  glm::vec3 position;
  glm::vec4 colour;  // sRGB + alpha
};

struct ColouredVertex {
  glm::vec3 position;
  glm::vec4 colour;
};

struct Marker {
  glm::vec3 position{0.0f};
  glm::vec4 fill{1.0f, 1.0f, 1.0f, 1.0f};
  glm::vec4 outline{0.0f, 0.0f, 0.0f, 1.0f};
  float radius_px = 4.0f;   // outer radius in pixels, outline included
  float outline_px = 1.0f;  // 0 for no outline
};

enum class TextAnchor {
  top_left,
  top,
  top_right,
  left,
  centre,
  right,
  bottom_left,
  bottom,
  bottom_right
};

struct TextLabel {
  glm::vec3 position{0.0f};  // world (3D) or image pixels (2D)
  std::string text;
  glm::vec4 colour{1.0f, 1.0f, 1.0f, 1.0f};
  TextAnchor anchor = TextAnchor::centre;  // which point of the text box sits at `position`
  glm::vec2 offset_px{0.0f};               // added after projection, image pixels (y down)
  glm::vec4 background{0.0f};              // box behind the text when alpha > 0
};

class DrawList {
 public:
  struct MeshItem {
    const GpuMesh* mesh;
    glm::mat4 model;
    Material material;
  };
  struct PolylineRange {
    std::size_t first;  // into line_vertices()
    std::size_t count;
    float width_px;
    bool closed;
  };

  // `mesh` must stay alive until the list is drawn.
  void add_mesh(const GpuMesh& mesh, const glm::mat4& model, const Material& material);
  // A connected line of screen-space width `width_px` with mitred joins.
  void add_polyline(std::span<const LineVertex> vertices, float width_px, bool closed = false);
  void add_polyline(std::span<const glm::vec3> points, const glm::vec4& colour, float width_px,
                    bool closed = false);
  void add_line(const glm::vec3& a, const glm::vec3& b, const glm::vec4& colour, float width_px);
  void add_marker(const Marker& marker);
  // Filled triangles (three vertices each), unlit; drawn before lines.
  void add_triangles(std::span<const ColouredVertex> vertices);
  // Square dots `size_px` pixels wide, one per vertex, unlit and not
  // anti-aliased; drawn with the triangles (depth tested and written in a 3D
  // view). For many points at once (a cloud of states): one vertex a dot
  // costs llvmpipe a fraction of a square made of two triangles.
  void add_dots(std::span<const ColouredVertex> centres, float size_px);
  // A filled axis-aligned rectangle in the xy plane (for 2D panels).
  void add_rect(const glm::vec2& min, const glm::vec2& max, const glm::vec4& colour);
  void add_text(TextLabel label);
  void clear();

  const std::vector<MeshItem>& meshes() const { return meshes_; }
  const std::vector<LineVertex>& line_vertices() const { return line_vertices_; }
  const std::vector<PolylineRange>& polylines() const { return polylines_; }
  const std::vector<Marker>& markers() const { return markers_; }
  const std::vector<ColouredVertex>& triangles() const { return triangles_; }
  struct DotRange {
    std::size_t first;  // into dot_vertices()
    std::size_t count;
    float size_px;
  };
  const std::vector<ColouredVertex>& dot_vertices() const { return dot_vertices_; }
  const std::vector<DotRange>& dots() const { return dots_; }
  const std::vector<TextLabel>& labels() const { return labels_; }

 private:
  std::vector<MeshItem> meshes_;
  std::vector<LineVertex> line_vertices_;
  std::vector<PolylineRange> polylines_;
  std::vector<Marker> markers_;
  std::vector<ColouredVertex> dot_vertices_;
  std::vector<DotRange> dots_;
  std::vector<ColouredVertex> triangles_;
  std::vector<TextLabel> labels_;
};

}  // namespace epviz::render
