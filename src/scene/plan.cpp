#include "scene/plan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "scene/frame_source.hpp"

namespace epviz::scene {

int SceneSettings::frame_count() const { return std::max(1, int(std::lround(fps * duration))); }

double ScenePlan::frame_time(int frame) const {
  return frames <= 1 ? 0.0 : run.t_end * double(frame) / double(frames - 1);
}

FrameLayout planned_layout(const SceneSettings& s, const sim::RunSpec& run) {
  LayoutRequest q;
  q.width = s.width;
  q.height = s.height;
  q.layers = s.layers;
  q.overlay = {kOverlayLines, overlay_drift_rows(run)};
  q.camera_distance = s.camera.distance;
  q.plane_extent = s.plane_extent;
  return frame_layout(q);
}

void trail_pixel_scales(const SceneSettings& s, double& sphere_px, double& plane_px) {
  LayoutRequest q;
  q.width = s.width;
  q.height = s.height;
  q.camera_distance = s.camera.distance;
  q.plane_extent = s.plane_extent;
  q.layers = {false, true, false, false};
  sphere_px = frame_layout(q).sphere_px_per_unit;
  q.layers = {false, false, true, false};
  plane_px = frame_layout(q).plane_px_per_unit;
}

double pixels_per_gamma(const FrameLayout& l, float plane_extent) {
  // d(a, b) = d(gamma) (1 + |eta|^2) / 2: the plane magnifies errors towards its edge.
  const double e2 = double(plane_extent) * plane_extent;
  return std::max({1.0, l.sphere_px_per_unit, l.plane_px_per_unit * (1.0 + e2) / 2.0});
}

double tolerance_for_layout(const FrameLayout& l, float plane_extent, double t_end) {
  const double tol = 0.02 / pixels_per_gamma(l, plane_extent) / (1.0 + t_end / 10.0);
  return std::clamp(tol, 1e-13, 1e-4);
}

ScenePlan plan_scene(sim::RunSpec run, const SceneSettings& s) {
  ScenePlan plan;
  const bool needs_attitude = s.view == View::space;
  if (needs_attitude) {
    if (s.formulation_given && run.formulation != sim::Formulation::spinor)
      throw PlanError(
          "view 'space' draws the body turning in space and needs its attitude, which only "
          "formulation spinor integrates; got formulation " +
          std::string(sim::name(run.formulation)));
    run.formulation = sim::Formulation::spinor;
  } else if (!s.formulation_given) {
    // gamma alone: the 6-dimensional direct state is the least the scene needs
    // that every method accepts.
    run.formulation = sim::Formulation::direct;
  }
  if (auto why = sim::incompatibility(run.method, run.formulation)) throw PlanError(*why);
  plan.layout = planned_layout(s, run);
  trail_pixel_scales(s, plan.trail_sphere_px, plan.trail_plane_px);

  char note[160];
  if (sim::is_adaptive(run.method)) {
    if (s.auto_tolerance) {
      run.tol = tolerance_for_layout(plan.layout, s.plane_extent, run.t_end);
      std::snprintf(note, sizeof note, "tol %.2g (auto)", run.tol);
    } else {
      std::snprintf(note, sizeof note, "tol %.2g", run.tol);
    }
  } else {
    std::snprintf(note, sizeof note, "step %.3g", run.step);
  }
  plan.accuracy_note = note;

  plan.frames = s.frame_count();
  plan.run = run;
  plan.run.samples = std::max(1, plan.frames - 1) * plan.samples_per_frame;
  return plan;
}

}  // namespace epviz::scene
