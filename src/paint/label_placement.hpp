#pragma once
// Where text labels go so that they do not cover each other, the marks they
// name, or what lies outside their part of the picture: each label offers a
// few positions in order of preference and takes the first free one. Plain
// geometry in image pixels (y down), no GL.
#include <string>
#include <vector>

#include <glm/vec2.hpp>

namespace epviz::paint {

struct Box {
  glm::vec2 min{0.0f}, max{0.0f};  // top left, bottom right
  float width() const { return max.x - min.x; }
  float height() const { return max.y - min.y; }
  bool intersects(const Box& o) const {
    return min.x < o.max.x && o.min.x < max.x && min.y < o.max.y && o.min.y < max.y;
  }
  bool contains(const Box& o) const {
    return o.min.x >= min.x && o.min.y >= min.y && o.max.x <= max.x && o.max.y <= max.y;
  }
  float overlap_area(const Box& o) const;
};
// A box of `size` centred on `centre`.
Box box_around(glm::vec2 centre, glm::vec2 size);

struct LabelRequest {
  std::string text;
  glm::vec2 size{0.0f};              // the text's extent in pixels
  std::vector<glm::vec2> top_lefts;  // candidate positions, most preferred first
};

// Places the labels in order: each takes its first candidate that lies inside
// `bounds` and meets neither an obstacle nor a label placed before it. Where
// none is free, the candidate that covers least (moved inside `bounds`).
// The result has a box per request, in the same order.
std::vector<Box> place_labels(const std::vector<LabelRequest>& labels, std::vector<Box> obstacles,
                              const Box& bounds);

// Candidate top-left corners for a label of `size` that names the point
// `anchor`: at `gap` pixels from it, first in the direction `outward` (image
// pixels; any length), then turning round it in eight steps each way.
std::vector<glm::vec2> candidates_around(glm::vec2 anchor, glm::vec2 size, glm::vec2 outward,
                                         float gap);

}  // namespace epviz::paint
