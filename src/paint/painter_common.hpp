#pragma once
// What the frame painter's files share: conversions to GLM, the ink that
// reads on a frame's background, and where the body's axis arrows end.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "scene/frame.hpp"
#include "scene/theme.hpp"

namespace epviz::paint {

inline glm::vec4 to_glm(const scene::Rgba& c) { return {c[0], c[1], c[2], c[3]}; }
inline glm::vec3 to_glm(const Eigen::Vector3f& v) { return {v.x(), v.y(), v.z()}; }
inline glm::quat to_glm(const Eigen::Quaternionf& q) { return {q.w(), q.x(), q.y(), q.z()}; }

// The frame's theme; where the job's own background is of the other kind, the
// built-in theme for that kind of background, so that lines and text still read.
const scene::Theme& ink_for(const scene::Frame& f);

// The length of the principal axes' arrows: past the centre of mass.
inline float axis_length(const scene::Frame& f) {
  return std::max(0.95f, f.body.centre_of_mass.norm() + 0.25f);
}

}  // namespace epviz::paint
