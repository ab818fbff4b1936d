#include "render/camera.hpp"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

namespace epviz::render {

glm::vec3 Camera::eye_position() const { return glm::vec3(glm::inverse(view)[3]); }

Camera Camera::look_at(const glm::vec3& eye, const glm::vec3& target, const glm::vec3& up,
                       float fov_y_degrees, float aspect, float near_plane, float far_plane) {
  return {glm::lookAt(eye, target, up),
          glm::perspective(glm::radians(fov_y_degrees), aspect, near_plane, far_plane)};
}

Camera Camera::orbit(const glm::vec3& target, float distance, float azimuth_degrees,
                     float elevation_degrees, float fov_y_degrees, float aspect) {
  const float azimuth = glm::radians(azimuth_degrees);
  const float elevation = glm::radians(elevation_degrees);
  const glm::vec3 direction(std::cos(elevation) * std::cos(azimuth),
                            std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
  // Near and far planes hug the scene so the depth buffer keeps its precision.
  return look_at(target + distance * direction, target, glm::vec3(0, 0, 1), fov_y_degrees, aspect,
                 distance * 0.05f, distance * 20.0f);
}

Camera Camera::pixel_space(int image_width, int image_height) {
  return {glm::mat4(1.0f), glm::ortho(0.0f, static_cast<float>(image_width),
                                      static_cast<float>(image_height), 0.0f, -1.0f, 1.0f)};
}

std::optional<glm::vec3> project_to_pixel(const Camera& camera, const Viewport& viewport,
                                          const glm::vec3& world) {
  const glm::vec4 clip = camera.view_projection() * glm::vec4(world, 1.0f);
  if (clip.w <= 1e-6f) return std::nullopt;
  const glm::vec3 ndc = glm::vec3(clip) / clip.w;
  return glm::vec3(
      static_cast<float>(viewport.x) + (ndc.x * 0.5f + 0.5f) * static_cast<float>(viewport.width),
      static_cast<float>(viewport.y) + (0.5f - ndc.y * 0.5f) * static_cast<float>(viewport.height),
      ndc.z * 0.5f + 0.5f);
}

}  // namespace epviz::render
