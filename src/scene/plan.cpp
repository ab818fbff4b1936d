#include "scene/plan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace epviz::scene {

int SceneSettings::frame_count() const { return std::max(1, int(std::lround(fps * duration))); }

double ScenePlan::frame_time(int frame) const {
  return frames <= 1 ? 0.0 : run.t_end * double(frame) / double(frames - 1);
}

// The painter gives the 3D view the left 60 % when the plane is shown, and the
// sphere (radius 1 at camera distance ~3.4) about 0.3 of the view's short side.
double sphere_pixels_per_unit(const SceneSettings& s) {
  const double w3d = s.layers.riccati ? 0.6 * s.width : double(s.width);
  return 0.3 * std::min(w3d, double(s.height));
}

double plane_pixels_per_unit(const SceneSettings& s) {
  const double side = std::min(s.layers.riccati && (s.layers.body || s.layers.sphere) ? 0.4 * s.width
                                                                                      : double(s.width),
                               double(s.height));
  return 0.8 * side / (2.0 * s.plane_extent);
}

double tolerance_for_resolution(const SceneSettings& s, double t_end) {
  // d(a, b) = d(gamma) (1 + |eta|^2) / 2: the plane magnifies errors towards its edge.
  const double e2 = double(s.plane_extent) * s.plane_extent;
  double px_per_gamma = s.layers.sphere || s.layers.body ? sphere_pixels_per_unit(s) : 1.0;
  if (s.layers.riccati) px_per_gamma = std::max(px_per_gamma, plane_pixels_per_unit(s) * (1.0 + e2) / 2.0);
  const double tol = 0.02 / px_per_gamma / (1.0 + t_end / 10.0);
  return std::clamp(tol, 1e-13, 1e-4);
}

ScenePlan plan_scene(sim::RunSpec run, const SceneSettings& s) {
  ScenePlan plan;
  const bool needs_attitude = s.view == View::space;
  if (needs_attitude) {
    if (s.formulation_given && run.formulation != sim::Formulation::spinor)
      throw PlanError("view 'space' draws the body turning in space and needs its attitude, which only "
                      "formulation spinor integrates; got formulation " +
                      std::string(sim::name(run.formulation)));
    run.formulation = sim::Formulation::spinor;
  } else if (!s.formulation_given) {
    // gamma alone: the 6-dimensional direct state is the least the scene needs
    // that every method accepts.
    run.formulation = sim::Formulation::direct;
  }
  if (auto why = sim::incompatibility(run.method, run.formulation)) throw PlanError(*why);

  char note[160];
  if (sim::is_adaptive(run.method)) {
    if (s.auto_tolerance) {
      run.tol = tolerance_for_resolution(s, run.t_end);
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
