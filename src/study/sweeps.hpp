#pragma once
// Fixed-step sweeps: how many steps over t_end the coarsest point takes, and
// how fast the step shrinks so that the error drops by about 100 per point.
#include <algorithm>
#include <cmath>

namespace epviz::study {

// Steps over t_end for a step of `fraction` of the fastest period.
inline long first_steps(double t_end, double period, double fraction) {
  return std::max(1L, long(std::ceil(t_end / (period * fraction))));
}

// Halvings of the step per sweep point for a method of this order (log2(100) / order, at least 1).
inline int halvings_per_point(int order) {
  return std::max(1, int(std::lround(std::log2(100.0) / double(std::max(order, 1)))));
}

}  // namespace epviz::study
