#pragma once
// Colour measures from their definitions, for checks that a picture reads:
// WCAG's contrast ratio and the CIELAB (D65) distance of two opaque sRGB
// colours. Written here, not taken from the code under test.
#include <algorithm>
#include <array>
#include <cmath>

namespace epviz::testing {

inline double srgb_to_linear(double c) {
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

template <class C>
double relative_luminance(const C& c) {
  return 0.2126 * srgb_to_linear(c[0]) + 0.7152 * srgb_to_linear(c[1]) +
         0.0722 * srgb_to_linear(c[2]);
}

template <class A, class B>
double contrast_ratio(const A& a, const B& b) {
  const double la = relative_luminance(a), lb = relative_luminance(b);
  return (std::max(la, lb) + 0.05) / (std::min(la, lb) + 0.05);
}

template <class C>
std::array<double, 3> cielab(const C& c) {
  const double r = srgb_to_linear(c[0]), g = srgb_to_linear(c[1]), b = srgb_to_linear(c[2]);
  const double x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
  const double y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  const double z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
  auto f = [](double t) {
    return t > 216.0 / 24389.0 ? std::cbrt(t) : (24389.0 / 27.0 * t + 16.0) / 116.0;
  };
  return {116.0 * f(y) - 16.0, 500.0 * (f(x) - f(y)), 200.0 * (f(y) - f(z))};
}

template <class A, class B>
double lab_distance(const A& a, const B& b) {
  const auto p = cielab(a), q = cielab(b);
  return std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
}

}  // namespace epviz::testing
