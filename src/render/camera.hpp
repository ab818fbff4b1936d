#pragma once
// Views: where a 3D scene or a 2D panel goes in the image, and how world
// coordinates map there. GLM is used here for view and projection only.
#include <optional>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace epviz::render {

// A rectangle of the image in pixels, origin at the top-left corner (image rows
// go down), as callers think of a picture; converted to GL's bottom-up internally.
struct Viewport {
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;

  float aspect() const {
    return height > 0 ? static_cast<float>(width) / static_cast<float>(height) : 1.0f;
  }
  // This rectangle shrunk by margins in pixels.
  Viewport inset(int left, int top, int right, int bottom) const {
    return {x + left, y + top, width - left - right, height - top - bottom};
  }
};

struct Camera {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};

  glm::mat4 view_projection() const { return projection * view; }
  glm::vec3 eye_position() const;

  // Perspective camera at `eye` looking at `target`.
  static Camera look_at(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up,
                        float fov_y_degrees, float aspect, float near_plane = 0.05f,
                        float far_plane = 100.0f);
  // Perspective camera on a sphere about `target`, z up: azimuth from +x towards
  // +y, elevation above the xy plane, both in degrees.
  static Camera orbit(const glm::vec3& target, float distance, float azimuth_degrees,
                      float elevation_degrees, float fov_y_degrees, float aspect);
  // Image-pixel coordinates of `viewport` (x right, y down, z ignored): for 2D drawing.
  static Camera pixel_space(int image_width, int image_height);
};

// Where `world` lands in image pixels (top-left origin) inside `viewport`, and
// its depth in [0, 1]; nullopt when it is behind the camera.
std::optional<glm::vec3> project_to_pixel(const Camera& camera, const Viewport& viewport,
                                          const glm::vec3& world);

}  // namespace epviz::render
