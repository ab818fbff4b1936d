#pragma once
// The small scene the frame-file and gallery tests draw: a case's short run
// (DOP853, T = 4, 100 samples) planned at 160×120 for one second at 10
// frames/s, and the one painter of that size they share.
#include "paint/frame_painter.hpp"
#include "physics/cases.hpp"
#include "render/render_test_support.hpp"
#include "scene/plan.hpp"
#include "sim/run_spec.hpp"

namespace epviz::testing {

inline constexpr int kSmallWidth = 160, kSmallHeight = 120;

struct SmallScene {
  scene::SceneSettings settings;
  scene::ScenePlan plan;
};

inline SmallScene small_scene(physics::Case c) {
  SmallScene s;
  s.settings.width = kSmallWidth;
  s.settings.height = kSmallHeight;
  s.settings.fps = 10;
  s.settings.duration = 1;
  s.plan = scene::plan_scene(
      sim::preset_run(c, sim::Method::dop853, sim::Formulation::direct, 4.0, 100), s.settings);
  return s;
}

inline paint::FramePainter& small_painter() {
  static paint::FramePainter p(shared_gl_context(), kSmallWidth, kSmallHeight,
                               {.builtin_font = true});
  return p;
}

}  // namespace epviz::testing
