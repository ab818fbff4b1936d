#pragma once
// Colour maps for time-coloured trails. A map is a few control points in the
// OKLab perceptual colour space, interpolated there and converted to sRGB, so
// lightness (and thus the reading of "earlier" vs "later") changes evenly.
#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace epviz::render {

struct OkLch {
  float lightness;  // 0 (black) .. 1 (white)
  float chroma;     // 0 (grey) .. ~0.3
  float hue_degrees;
};

class ColourMap {
 public:
  // Control points spread evenly over [0, 1], at least two.
  ColourMap(std::string name, std::vector<OkLch> control_points);

  // The colour at t in [0, 1] (clamped), sRGB with the given alpha.
  glm::vec4 operator()(float t, float alpha = 1.0f) const;
  const std::string& name() const { return name_; }

  // Dark violet -> blue -> teal -> green -> yellow with lightness rising
  // linearly from 0.30 to 0.93 (viridis-like in spirit, computed here).
  static ColourMap time();
  // Cool-to-warm diverging map (blue -> light grey -> red) for signed values.
  static ColourMap diverging();

 private:
  std::string name_;
  std::vector<glm::vec3> lab_;  // control points as OKLab (L, a, b)
};

}  // namespace epviz::render
