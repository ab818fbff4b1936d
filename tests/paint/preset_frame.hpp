#pragma once
// The frame the painter tests draw: a preset's short run (DOP853, T = 12, 200
// samples) planned as `epviz render` plans it with the caller's settings, at
// 3 s and 10 frames/s, and its frame 18, 60 % of the way.
#include "physics/cases.hpp"
#include "scene/frame_source.hpp"
#include "sim/run_spec.hpp"

namespace epviz::testing {

inline scene::Frame preset_frame(physics::Case c, scene::SceneSettings s) {
  const auto run = sim::preset_run(c, sim::Method::dop853, sim::Formulation::direct, 12.0, 200);
  s.fps = 10;
  s.duration = 3;
  scene::FrameSource source(scene::plan_scene(run, s), s);
  return source.frame(18);
}

}  // namespace epviz::testing
