#include "paint/label_placement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <glm/geometric.hpp>

namespace epviz::paint {

float Box::overlap_area(const Box& o) const {
  const float w = std::min(max.x, o.max.x) - std::max(min.x, o.min.x);
  const float h = std::min(max.y, o.max.y) - std::max(min.y, o.min.y);
  return w > 0.0f && h > 0.0f ? w * h : 0.0f;
}

Box box_around(glm::vec2 centre, glm::vec2 size) {
  return {centre - 0.5f * size, centre + 0.5f * size};
}

namespace {

// The box moved (not resized) to lie inside `bounds` as far as it fits.
Box moved_inside(Box b, const Box& bounds) {
  glm::vec2 shift(0.0f);
  if (b.max.x > bounds.max.x) shift.x = bounds.max.x - b.max.x;
  if (b.min.x + shift.x < bounds.min.x) shift.x = bounds.min.x - b.min.x;
  if (b.max.y > bounds.max.y) shift.y = bounds.max.y - b.max.y;
  if (b.min.y + shift.y < bounds.min.y) shift.y = bounds.min.y - b.min.y;
  return {b.min + shift, b.max + shift};
}

float covered(const Box& b, const std::vector<Box>& taken) {
  float sum = 0.0f;
  for (const auto& t : taken) sum += b.overlap_area(t);
  return sum;
}

}  // namespace

std::vector<Box> place_labels(const std::vector<LabelRequest>& labels, std::vector<Box> obstacles,
                              const Box& bounds) {
  std::vector<Box> placed;
  placed.reserve(labels.size());
  for (const auto& l : labels) {
    std::optional<Box> chosen;
    Box least{};
    float least_cover = std::numeric_limits<float>::infinity();
    for (const auto& tl : l.top_lefts) {
      const Box b{tl, tl + l.size};
      const bool inside = bounds.contains(b);
      if (inside && covered(b, obstacles) == 0.0f) {
        chosen = b;
        break;
      }
      const Box in = moved_inside(b, bounds);
      const float c = covered(in, obstacles);
      if (c < least_cover) {
        least_cover = c;
        least = in;
      }
    }
    const Box b = chosen ? *chosen : least;
    placed.push_back(b);
    obstacles.push_back(b);
  }
  return placed;
}

std::vector<glm::vec2> candidates_around(glm::vec2 anchor, glm::vec2 size, glm::vec2 outward,
                                         float gap) {
  const float len = glm::length(outward);
  const float start = len > 1e-6f ? std::atan2(outward.y, outward.x) : -1.5707963f;  // up
  std::vector<glm::vec2> out;
  // The box's centre on an ellipse round the anchor, far enough that the
  // box clears the anchor by `gap` in every direction.
  const glm::vec2 half = 0.5f * size + glm::vec2(gap);
  for (int k = 0; k <= 8; ++k)
    for (int sign : {1, -1}) {
      if (k == 0 && sign < 0) continue;
      if (k == 8 && sign < 0) continue;
      const float a = start + float(sign * k) * 0.3926991f;  // pi / 8
      const glm::vec2 d(std::cos(a), std::sin(a));
      // Scale the direction so that the box just clears: the larger of the
      // two axis-wise distances.
      const float s = std::min(std::abs(d.x) > 1e-6f ? half.x / std::abs(d.x) : 1e9f,
                               std::abs(d.y) > 1e-6f ? half.y / std::abs(d.y) : 1e9f);
      out.push_back(anchor + d * s - 0.5f * size);
    }
  return out;
}

}  // namespace epviz::paint
