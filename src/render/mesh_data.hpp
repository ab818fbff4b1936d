#pragma once
// Triangle meshes as plain data (no GL), and builders for the simple shapes a
// frame needs: spheres, ellipsoids, boxes, cylinders, cones and arrows, plus the
// latitude/longitude grid of a sphere as polylines.
#include <cstdint>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace epviz::render {

struct MeshData {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;      // one per position, unit length
  std::vector<std::uint32_t> indices;  // triangles, counter-clockwise seen from outside
};

// Appends `part` transformed by `transform` (normals by its inverse transpose).
void append_mesh(MeshData& mesh, const MeshData& part,
                 const glm::mat4& transform = glm::mat4(1.0f));

// Sphere of `radius` about the origin; `slices` around the z axis, `stacks` from pole to pole.
MeshData make_uv_sphere(float radius = 1.0f, int slices = 48, int stacks = 24);
// Ellipsoid with semi-axes `radii` along x, y, z (a scaled sphere with correct normals).
// Box centred on the origin with flat faces.
MeshData make_box(const glm::vec3& half_extents);
// Cylinder along +z from z = 0 to z = length.
MeshData make_cylinder(float radius, float length, int segments = 32, bool caps = true);
// Cone along +z, base of `radius` at z = 0, apex at z = length.
MeshData make_cone(float radius, float length, int segments = 32, bool base_cap = true);
// Arrow along +z from the origin to z = length: a cylinder shaft and a cone head.
MeshData make_arrow(float length, float shaft_radius, float head_radius, float head_length,
                    int segments = 32);

// A rotation taking +z onto `direction` (any length > 0), for placing arrows and cylinders.
glm::mat4 rotation_from_z_to(const glm::vec3& direction);

// Latitude/longitude grid on a sphere of `radius` about the origin, poles on ±z:
// `parallels` circles of latitude strictly between the poles (equally spaced in
// latitude) and `meridians` half circles from pole to pole. Each polyline has
// `points_per_circle` points per full turn; circles are closed (last = first).
std::vector<std::vector<glm::vec3>> make_lat_long_grid(float radius, int parallels, int meridians,
                                                       int points_per_circle = 96);

}  // namespace epviz::render
