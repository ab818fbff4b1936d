#include "render/colour_map.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace epviz::render {
namespace {

glm::vec3 oklch_to_oklab(const OkLch& c) {
  const float h = c.hue_degrees * std::numbers::pi_v<float> / 180.0f;
  return {c.lightness, c.chroma * std::cos(h), c.chroma * std::sin(h)};
}

float linear_to_srgb(float x) {
  x = std::clamp(x, 0.0f, 1.0f);
  return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

// OKLab -> linear sRGB, with Björn Ottosson's published OKLab matrices.
glm::vec3 oklab_to_srgb(const glm::vec3& lab) {
  const float l_ = lab.x + 0.3963377774f * lab.y + 0.2158037573f * lab.z;
  const float m_ = lab.x - 0.1055613458f * lab.y - 0.0638541728f * lab.z;
  const float s_ = lab.x - 0.0894841775f * lab.y - 1.2914855480f * lab.z;
  const float l = l_ * l_ * l_, m = m_ * m_ * m_, s = s_ * s_ * s_;
  const float r = 4.0767416621f * l - 3.3077115913f * m + 0.2309699292f * s;
  const float g = -1.2684380046f * l + 2.6097574011f * m - 0.3413193965f * s;
  const float b = -0.0041960863f * l - 0.7034186147f * m + 1.7076147010f * s;
  return {linear_to_srgb(r), linear_to_srgb(g), linear_to_srgb(b)};
}

}  // namespace

ColourMap::ColourMap(std::string name, std::vector<OkLch> control_points) : name_(std::move(name)) {
  if (control_points.size() < 2)
    throw std::invalid_argument("a colour map needs at least two control points");
  for (const auto& point : control_points) lab_.push_back(oklch_to_oklab(point));
}

glm::vec4 ColourMap::operator()(float t, float alpha) const {
  if (!(t >= 0.0f)) t = 0.0f;  // also catches NaN
  t = std::min(t, 1.0f);
  const float position = t * static_cast<float>(lab_.size() - 1);
  const auto index = std::min(static_cast<std::size_t>(position), lab_.size() - 2);
  const float f = position - static_cast<float>(index);
  // Interpolating in Cartesian OKLab (not in hue) keeps the path short and smooth.
  const glm::vec3 lab = lab_[index] * (1.0f - f) + lab_[index + 1] * f;
  return glm::vec4(oklab_to_srgb(lab), alpha);
}

ColourMap ColourMap::time() {
  // Lightness rises linearly with t (0.30 -> 0.93): equal steps in time read as
  // equal steps in brightness; hue turns from violet through blue and green
  // to yellow, chroma is kept moderate so every point stays inside sRGB.
  constexpr int n = 5;
  const float hues[n] = {310.0f, 255.0f, 190.0f, 145.0f, 105.0f};
  const float chromas[n] = {0.13f, 0.11f, 0.10f, 0.15f, 0.18f};
  std::vector<OkLch> points;
  for (int i = 0; i < n; ++i) {
    const float t = static_cast<float>(i) / static_cast<float>(n - 1);
    points.push_back({0.30f + 0.63f * t, chromas[i], hues[i]});
  }
  return ColourMap("time", std::move(points));
}

ColourMap ColourMap::diverging() {
  return ColourMap("diverging",
                   {{0.45f, 0.15f, 262.0f}, {0.92f, 0.01f, 262.0f}, {0.50f, 0.17f, 28.0f}});
}

}  // namespace epviz::render
