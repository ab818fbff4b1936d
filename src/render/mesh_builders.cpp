#include "render/mesh_data.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>

namespace epviz::render {
namespace {

constexpr float pi = std::numbers::pi_v<float>;

void require(bool condition, const char* message) {
  if (!condition) throw std::invalid_argument(message);
}

// A ring of `segments` + 1 vertices (the seam is duplicated so normals may differ
// per ring) at height z; returns the index of its first vertex.
std::uint32_t add_ring(MeshData& mesh, float radius, float z, int segments,
                       const glm::vec3& normal_tilt, bool radial_normals) {
  const auto first = static_cast<std::uint32_t>(mesh.positions.size());
  for (int i = 0; i <= segments; ++i) {
    const float angle = 2.0f * pi * static_cast<float>(i) / static_cast<float>(segments);
    const glm::vec3 radial(std::cos(angle), std::sin(angle), 0.0f);
    mesh.positions.push_back(radius * radial + glm::vec3(0, 0, z));
    mesh.normals.push_back(radial_normals ? glm::normalize(radial + normal_tilt) : normal_tilt);
  }
  return first;
}

void connect_rings(MeshData& mesh, std::uint32_t lower, std::uint32_t upper, int segments) {
  for (int i = 0; i < segments; ++i) {
    const auto a = lower + static_cast<std::uint32_t>(i);
    const auto b = upper + static_cast<std::uint32_t>(i);
    mesh.indices.insert(mesh.indices.end(), {a, a + 1, b + 1, a, b + 1, b});
  }
}

// A flat disc at height z facing +z (up) or -z.
void add_disc(MeshData& mesh, float radius, float z, int segments, bool facing_up) {
  const auto centre = static_cast<std::uint32_t>(mesh.positions.size());
  const glm::vec3 normal(0, 0, facing_up ? 1.0f : -1.0f);
  mesh.positions.emplace_back(0, 0, z);
  mesh.normals.push_back(normal);
  const auto ring = add_ring(mesh, radius, z, segments, normal, false);
  for (int i = 0; i < segments; ++i) {
    const auto a = ring + static_cast<std::uint32_t>(i);
    if (facing_up)
      mesh.indices.insert(mesh.indices.end(), {centre, a, a + 1});
    else
      mesh.indices.insert(mesh.indices.end(), {centre, a + 1, a});
  }
}

}  // namespace

void append_mesh(MeshData& mesh, const MeshData& part, const glm::mat4& transform) {
  const auto base = static_cast<std::uint32_t>(mesh.positions.size());
  const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(transform)));
  for (std::size_t i = 0; i < part.positions.size(); ++i) {
    mesh.positions.push_back(glm::vec3(transform * glm::vec4(part.positions[i], 1.0f)));
    mesh.normals.push_back(glm::normalize(normal_matrix * part.normals[i]));
  }
  for (auto index : part.indices) mesh.indices.push_back(base + index);
}

MeshData make_uv_sphere(float radius, int slices, int stacks) {
  require(radius > 0 && slices >= 3 && stacks >= 2,
          "sphere needs radius > 0, slices >= 3, stacks >= 2");
  MeshData mesh;
  for (int j = 0; j <= stacks; ++j) {
    const float polar = pi * static_cast<float>(j) / static_cast<float>(stacks);  // 0 at +z
    for (int i = 0; i <= slices; ++i) {
      const float azimuth = 2.0f * pi * static_cast<float>(i) / static_cast<float>(slices);
      const glm::vec3 n(std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                        std::cos(polar));
      mesh.positions.push_back(radius * n);
      mesh.normals.push_back(n);
    }
  }
  const auto row = static_cast<std::uint32_t>(slices + 1);
  for (int j = 0; j < stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      const auto a = static_cast<std::uint32_t>(j) * row + static_cast<std::uint32_t>(i);
      const auto b = a + row;
      // Skip the degenerate triangle at each pole.
      if (j != 0) mesh.indices.insert(mesh.indices.end(), {a, b, a + 1});
      if (j != stacks - 1) mesh.indices.insert(mesh.indices.end(), {a + 1, b, b + 1});
    }
  }
  return mesh;
}

MeshData make_box(const glm::vec3& half_extents) {
  require(half_extents.x > 0 && half_extents.y > 0 && half_extents.z > 0,
          "box half extents must be positive");
  MeshData mesh;
  // Each face gets its own four vertices so its normal is flat.
  for (int axis = 0; axis < 3; ++axis) {
    for (float sign : {1.0f, -1.0f}) {
      glm::vec3 normal(0.0f);
      normal[axis] = sign;
      glm::vec3 u(0.0f), v(0.0f);
      u[(axis + 1) % 3] = 1.0f;
      v[(axis + 2) % 3] = 1.0f;
      if (sign < 0) std::swap(u, v);  // keep counter-clockwise seen from outside
      const auto first = static_cast<std::uint32_t>(mesh.positions.size());
      for (auto [su, sv] : {std::pair{-1.0f, -1.0f}, {1.0f, -1.0f}, {1.0f, 1.0f}, {-1.0f, 1.0f}}) {
        mesh.positions.push_back((normal + su * u + sv * v) * half_extents);
        mesh.normals.push_back(normal);
      }
      mesh.indices.insert(mesh.indices.end(),
                          {first, first + 1, first + 2, first, first + 2, first + 3});
    }
  }
  return mesh;
}

MeshData make_cylinder(float radius, float length, int segments, bool caps) {
  require(radius > 0 && length > 0 && segments >= 3,
          "cylinder needs radius > 0, length > 0, segments >= 3");
  MeshData mesh;
  const auto lower = add_ring(mesh, radius, 0.0f, segments, glm::vec3(0.0f), true);
  const auto upper = add_ring(mesh, radius, length, segments, glm::vec3(0.0f), true);
  connect_rings(mesh, lower, upper, segments);
  if (caps) {
    add_disc(mesh, radius, 0.0f, segments, false);
    add_disc(mesh, radius, length, segments, true);
  }
  return mesh;
}

MeshData make_cone(float radius, float length, int segments, bool base_cap) {
  require(radius > 0 && length > 0 && segments >= 3,
          "cone needs radius > 0, length > 0, segments >= 3");
  MeshData mesh;
  // The side's normals lean towards the apex by the slope of the cone.
  const glm::vec3 tilt(0.0f, 0.0f, radius / length);
  const auto base = add_ring(mesh, radius, 0.0f, segments, tilt, true);
  // A ring of apex copies, each with the normal of its slice, for smooth shading.
  const auto apex = static_cast<std::uint32_t>(mesh.positions.size());
  for (int i = 0; i <= segments; ++i) {
    const float angle = 2.0f * pi * (static_cast<float>(i) + 0.5f) / static_cast<float>(segments);
    mesh.positions.emplace_back(0.0f, 0.0f, length);
    mesh.normals.push_back(
        glm::normalize(glm::vec3(std::cos(angle), std::sin(angle), 0.0f) + tilt));
  }
  for (int i = 0; i < segments; ++i) {
    const auto a = base + static_cast<std::uint32_t>(i);
    mesh.indices.insert(mesh.indices.end(), {a, a + 1, apex + static_cast<std::uint32_t>(i)});
  }
  if (base_cap) add_disc(mesh, radius, 0.0f, segments, false);
  return mesh;
}

MeshData make_arrow(float length, float shaft_radius, float head_radius, float head_length,
                    int segments) {
  require(length > head_length && head_length > 0 && head_radius > shaft_radius && shaft_radius > 0,
          "arrow needs length > head_length > 0 and head_radius > shaft_radius > 0");
  MeshData mesh = make_cylinder(shaft_radius, length - head_length, segments, true);
  append_mesh(mesh, make_cone(head_radius, head_length, segments, true),
              glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, length - head_length)));
  return mesh;
}

glm::mat4 rotation_from_z_to(const glm::vec3& direction) {
  const float length = glm::length(direction);
  require(length > 0, "rotation_from_z_to needs a non-zero direction");
  const glm::vec3 d = direction / length;
  const glm::vec3 z(0, 0, 1);
  const float c = glm::dot(z, d);
  if (c > 1.0f - 1e-6f) return glm::mat4(1.0f);
  if (c < -1.0f + 1e-6f) return glm::rotate(glm::mat4(1.0f), pi, glm::vec3(1, 0, 0));
  return glm::rotate(glm::mat4(1.0f), std::acos(c), glm::normalize(glm::cross(z, d)));
}

std::vector<std::vector<glm::vec3>> make_lat_long_grid(float radius, int parallels, int meridians,
                                                       int points_per_circle) {
  require(radius > 0 && parallels >= 0 && meridians >= 0 && points_per_circle >= 8,
          "grid needs radius > 0, counts >= 0 and at least 8 points per circle");
  std::vector<std::vector<glm::vec3>> lines;
  for (int k = 1; k <= parallels; ++k) {
    const float latitude = -pi / 2 + pi * static_cast<float>(k) / static_cast<float>(parallels + 1);
    std::vector<glm::vec3> circle;
    for (int i = 0; i <= points_per_circle; ++i) {
      const float azimuth =
          2.0f * pi * static_cast<float>(i) / static_cast<float>(points_per_circle);
      circle.push_back(radius * glm::vec3(std::cos(latitude) * std::cos(azimuth),
                                          std::cos(latitude) * std::sin(azimuth),
                                          std::sin(latitude)));
    }
    lines.push_back(std::move(circle));
  }
  const int half = points_per_circle / 2;
  for (int k = 0; k < meridians; ++k) {
    const float azimuth = 2.0f * pi * static_cast<float>(k) / static_cast<float>(meridians);
    std::vector<glm::vec3> half_circle;
    for (int i = 0; i <= half; ++i) {
      const float polar = pi * static_cast<float>(i) / static_cast<float>(half);
      half_circle.push_back(radius * glm::vec3(std::sin(polar) * std::cos(azimuth),
                                               std::sin(polar) * std::sin(azimuth),
                                               std::cos(polar)));
    }
    lines.push_back(std::move(half_circle));
  }
  return lines;
}

}  // namespace epviz::render
