#include "scene/plan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "numerics/failure.hpp"
#include "scene/frame_source.hpp"
#include "scene/run_track.hpp"

namespace epviz::scene {

int SceneSettings::frame_count() const { return std::max(1, int(std::lround(fps * duration))); }

double ScenePlan::frame_time(int frame) const {
  return frames <= 1 ? 0.0 : run.t_end * double(frame) / double(frames - 1);
}

FrameLayout planned_layout(const SceneSettings& s, const sim::RunSpec& run) {
  return planned_layout(s, std::vector<sim::RunSpec>{run});
}

namespace {

LayoutRequest planned_request(const SceneSettings& s, const std::vector<sim::RunSpec>& runs) {
  LayoutRequest q;
  q.width = s.width;
  q.height = s.height;
  q.layers = s.layers;
  q.overlay = {kOverlayLines, overlay_drift_rows(runs)};
  q.camera_distance = s.camera.distance;
  q.plane_extent = s.plane_extent;
  q.chart_height = runs.size() > 1 ? comparison_chart_height(s.page.type_height_for(s.height)) : 0;
  q.legend_rows = runs.size() > 1 ? comparison_legend_rows(int(runs.size())) : 0;
  q.section_panel = s.section.has_value();
  q.page = s.page;
  return q;
}

}  // namespace

FrameLayout planned_layout(const SceneSettings& s, const std::vector<sim::RunSpec>& runs) {
  return frame_layout(planned_request(s, runs));
}

void set_printed_size(SceneSettings& s, const std::vector<sim::RunSpec>& runs, int width,
                      float font_px) {
  s.width = width;
  s.page.type_height = type_height_for_font(font_px);
  s.page.stacked = true;
  // Even, so that a video encoder takes it too.
  s.height = (stacked_height(planned_request(s, runs)) + 1) / 2 * 2;
}

void trail_pixel_scales(const SceneSettings& s, double& sphere_px, double& plane_px) {
  LayoutRequest q;
  q.width = s.width;
  q.height = s.height;
  q.camera_distance = s.camera.distance;
  q.plane_extent = s.plane_extent;
  q.page = s.page;
  q.layers = Layers::only({Layer::sphere});
  sphere_px = frame_layout(q).sphere_px_per_unit;
  q.layers = Layers::only({Layer::riccati});
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

sim::RunSpec shadow_run(const sim::RunSpec& run) {
  sim::RunSpec shadow = run;
  if (sim::is_adaptive(run.method))
    shadow.tol = std::max(run.tol * 1e-2, 1e-15);
  else
    shadow.step = run.step * 0.5;
  // The shadow only measures: it must not end the scene where the run itself goes on.
  shadow.max_drift = std::numeric_limits<double>::infinity();
  return shadow;
}

double shadow_error_factor(const sim::RunSpec& run) {
  if (sim::is_adaptive(run.method)) return 1.0;
  const double gain = std::pow(2.0, sim::order(run.method));
  return gain / (gain - 1.0);
}

namespace {

// The formulation the view needs and the accuracy the layout needs, for one
// run; `note` says which accuracy was chosen and how.
sim::RunSpec resolve_run(sim::RunSpec run, bool formulation_given, bool auto_tolerance,
                         const SceneSettings& s, const FrameLayout& layout, std::string& note) {
  const bool needs_attitude = s.view == View::space;
  if (needs_attitude) {
    if (formulation_given && run.formulation != sim::Formulation::spinor)
      throw PlanError(
          "view 'space' draws the body turning in space and needs its attitude, which only "
          "formulation spinor integrates; got formulation " +
          std::string(sim::name(run.formulation)));
    run.formulation = sim::Formulation::spinor;
  } else if (!formulation_given) {
    // gamma alone: the 6-dimensional direct state is the least the scene needs
    // that every method accepts.
    run.formulation = sim::Formulation::direct;
  }
  if (auto why = sim::incompatibility(run.method, run.formulation)) throw PlanError(*why);

  char text[160];
  if (sim::is_adaptive(run.method)) {
    if (auto_tolerance) {
      run.tol = tolerance_for_layout(layout, s.plane_extent, run.t_end);
      std::snprintf(text, sizeof text, "tol %.2g (auto)", run.tol);
    } else {
      std::snprintf(text, sizeof text, "tol %.2g", run.tol);
    }
  } else {
    // The step is taken as given (sim::Trajectory): the note is the step used.
    std::snprintf(text, sizeof text, "step %.3g", run.step);
  }
  note = text;
  return run;
}

// The auto tolerance whose picture stays true longest (see plan_scene), for a
// run already resolved at the resolution's tolerance. The look-ahead is the
// render's own run and shadow (RunTrack) over the same samples, so the
// horizon it finds is the one the render reports; it stops at the first
// sample past half a pixel, and integrating costs little next to drawing.
double longest_true_tolerance(const sim::RunSpec& run, const SceneSettings& s,
                              const ScenePlan& plan) {
  const double ppg = pixels_per_gamma(plan.layout, s.plane_extent);
  double best_tol = run.tol, best_until = -1.0;
  for (double tol = run.tol;; tol = std::max(tol * 1e-2, kTightestAutoTolerance)) {
    sim::RunSpec trial = run;
    trial.tol = tol;
    RunTrack track(trial, s.view, s.trace_axis, plan.trail_sphere_px, plan.trail_plane_px, ppg,
                   true);
    double until = trial.t_end;
    try {
      for (int i = 0; i < trial.samples && !track.pixel_true_until(); ++i) track.advance();
      if (track.pixel_true_until()) until = *track.pixel_true_until();
    } catch (const numerics::IntegrationError&) {
      until = track.latest().t;  // the render stops here too, whatever the tolerance
    }
    if (!track.pixel_true_until() && until >= trial.t_end) return tol;
    if (until > best_until) {
      best_until = until;
      best_tol = tol;
    }
    if (tol <= kTightestAutoTolerance) return best_tol;
  }
}

}  // namespace

ScenePlan plan_scene(sim::RunSpec run, const SceneSettings& s, Horizon h) {
  return plan_scene(std::vector<RunRequest>{{run, "", s.formulation_given, s.auto_tolerance}}, s,
                    h);
}

ScenePlan plan_scene(std::vector<RunRequest> runs, const SceneSettings& s, Horizon h) {
  if (runs.empty()) throw PlanError("a scene needs at least one run");
  ScenePlan plan;
  plan.frames = s.frame_count();
  const int samples = std::max(1, plan.frames - 1) * plan.samples_per_frame;
  std::vector<sim::RunSpec> specs;
  for (auto& r : runs) {
    // Every run shares the first's frame times.
    r.run.t_end = runs.front().run.t_end;
    r.run.samples = samples;
    specs.push_back(r.run);
  }
  // An interactive scene (no horizon: its run has no end) draws no section
  // panel, whose crossings FrameSource finds to a render's end: its frames
  // are laid out without one, and so is its plan.
  SceneSettings laid = s;
  if (h == Horizon::none) laid.section.reset();
  plan.layout = planned_layout(laid, specs);
  trail_pixel_scales(s, plan.trail_sphere_px, plan.trail_plane_px);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    std::string note;
    const auto& r = runs[i];
    auto resolved = resolve_run(r.run, r.formulation_given, r.auto_tolerance, s, plan.layout, note);
    if (h == Horizon::search && r.auto_tolerance && sim::is_adaptive(resolved.method)) {
      const double tol = longest_true_tolerance(resolved, s, plan);
      if (tol != resolved.tol) {
        resolved.tol = tol;
        char text[64];
        std::snprintf(text, sizeof text, "tol %.2g (auto, tightened)", tol);
        note = text;
      }
    }
    if (i == 0) {
      plan.run = resolved;
      plan.accuracy_note = note;
      plan.label = runs.size() > 1 ? r.label : std::string();
    } else {
      plan.others.push_back({resolved, r.label, note});
    }
  }
  return plan;
}

}  // namespace epviz::scene
