#pragma once
// The independent check of a planned run's picture: its distance from a
// DOP853 run at tol 1e-13 over the same samples, in pixels of the picture.
#include <gtest/gtest.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "scene/plan.hpp"
#include "sim/simulate.hpp"

namespace epviz::testing {

// (t, error in pixels) at each sample time of `plan.run`.
inline std::vector<std::pair<double, double>> true_error_px(const scene::ScenePlan& plan,
                                                            float plane_extent = 2.5f) {
  auto spec = plan.run;
  const auto drawn = sim::simulate(spec);
  spec.tol = 1e-13;
  const auto truth = sim::simulate(spec);
  EXPECT_FALSE(drawn.failure);
  EXPECT_FALSE(truth.failure);
  const double px = scene::pixels_per_gamma(plan.layout, plane_extent);
  std::vector<std::pair<double, double>> errors;
  for (std::size_t i = 0; i < std::min(drawn.samples.size(), truth.samples.size()); ++i)
    errors.emplace_back(drawn.samples[i].t,
                        (drawn.samples[i].gamma - truth.samples[i].gamma).norm() * px);
  return errors;
}

}  // namespace epviz::testing
