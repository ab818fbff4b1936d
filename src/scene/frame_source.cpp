#include "scene/frame_source.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>

#include "physics/format.hpp"
#include "physics/stereographic.hpp"
#include "scene/body_shape.hpp"
#include "scene/plane_path.hpp"

namespace epviz::scene {
namespace {

std::string fmt3(const Eigen::Vector3d& v) { return physics::detail::vec(v, 4); }

}  // namespace

std::string case_title(physics::Case c) {
  return c == physics::Case::custom ? "Heavy top" : std::string(physics::preset(c).title);
}

std::string extra_integral_symbol(physics::Case c) {
  return c == physics::Case::custom ? "" : std::string(physics::preset(c).integral_symbol);
}

int overlay_drift_rows(const sim::RunSpec& run) {
  return 3 + (sim::InvariantMonitor(run.body, run.case_id, run.initial).no_drift().extra ? 1 : 0);
}

FrameSource::FrameSource(const ScenePlan& plan, const SceneSettings& settings)
    : plan_(plan),
      settings_(settings),
      trajectory_(sim::Trajectory::start(plan.run)),
      monitor_(plan.run.body, plan.run.case_id, plan.run.initial),
      history_(plan.trail_sphere_px, plan.trail_plane_px),
      shape_(body_shape(plan.run.body)) {
  max_drift_ = monitor_.no_drift();
  take(trajectory_->initial());
}

void FrameSource::take(const sim::Sample& s) {
  latest_ = s;
  monitor_.worsen(max_drift_, s);

  HistoryPoint p;
  p.t = s.t;
  const Eigen::Vector3d on_sphere = settings_.view == View::space && s.attitude
                                        ? Eigen::Vector3d(*s.attitude * traced_axis())
                                        : s.gamma;
  p.sphere = on_sphere.cast<float>();
  if (auto ab = physics::stereographic(s.gamma)) p.plane = ab->cast<float>();
  p.gamma3 = float(s.gamma.z());
  history_.offer(p);
}

Frame FrameSource::frame(int index) {
  const long target = long(index) * plan_.samples_per_frame;
  while (sample_index_ < target) {
    take(trajectory_->next());
    ++sample_index_;
  }
  history_.forget_before(latest_.t - trail_window());
  return compose(index);
}

Eigen::Vector3d FrameSource::traced_axis() const {
  return Eigen::Vector3d::Unit(std::clamp(settings_.trace_axis, 1, 3) - 1);
}

double FrameSource::trail_window() const {
  return settings_.trail_length > 0.0 ? settings_.trail_length : plan_.run.t_end;
}

Frame FrameSource::frame_at_time(double t) {
  const double spacing = trajectory_->spacing();
  // Half a spacing of slack: the sample nearest to t is taken, never one after it.
  while (latest_.t + 0.5 * spacing <= t) {
    take(trajectory_->next());
    ++sample_index_;
  }
  history_.forget_before(latest_.t - trail_window());
  return compose(++frames_composed_);
}

Frame FrameSource::compose(int index) const {
  Frame f;
  f.index = index;
  f.t = latest_.t;
  f.view = settings_.view;
  f.layers = settings_.layers;
  f.camera = settings_.camera;
  f.theme = settings_.theme;
  f.colours = settings_.colours;
  f.body = shape_;
  f.plane_extent = settings_.plane_extent;

  const double window = trail_window();
  auto age = [&](double t) { return float(std::clamp((latest_.t - t) / window, 0.0, 1.0)); };

  if (settings_.view == View::space && latest_.attitude) {
    f.body_rotation = latest_.attitude->cast<float>();
    f.current = (*latest_.attitude * traced_axis()).cast<float>();
    f.trail_label = "body axis " + std::to_string(settings_.trace_axis) + " (space frame)";
  } else {
    f.current = latest_.gamma.cast<float>();
    f.trail_label = "gamma (body frame)";
  }
  f.trail_time = window;
  const auto& pts = history_.points();
  f.trail.reserve(pts.size() + 1);
  for (const auto& p : pts) f.trail.push_back({p.sphere, age(p.t)});
  f.trail.push_back({f.current, 0.0f});

  auto path = build_plane_path(pts, f.plane_extent, age);
  f.plane_path = std::move(path.points);
  f.plane_marks = std::move(path.marks);
  if (auto ab = physics::stereographic(latest_.gamma)) {
    const Eigen::Vector2f now = ab->cast<float>();
    f.plane_path.push_back({now, 0.0f, false});
    if (inside_panel(now, f.plane_extent)) f.plane_current = now;
  }

  const auto& run = plan_.run;
  f.overlay.title = settings_.title.empty() ? case_title(run.case_id) : settings_.title;
  // Most important first: a small picture shows only the first lines.
  char line[160];
  if (plan_.open_ended)
    std::snprintf(line, sizeof line, "t = %.3f", latest_.t);
  else
    std::snprintf(line, sizeof line, "t = %.3f / %g", latest_.t, run.t_end);
  f.overlay.lines.emplace_back(line);
  f.overlay.lines.push_back(std::string(sim::name(run.method)) + ", " + plan_.accuracy_note);
  f.overlay.lines.push_back(std::string(sim::name(run.formulation)) + " formulation");
  std::snprintf(line, sizeof line, "I = %s", fmt3(run.body.inertia).c_str());
  f.overlay.lines.emplace_back(line);
  std::snprintf(line, sizeof line, "r = %s   P = %.4g", fmt3(run.body.com).c_str(),
                run.body.weight);
  f.overlay.lines.emplace_back(line);
  assert(int(f.overlay.lines.size()) == kOverlayLines);
  f.overlay.drifts = {{"|gamma|^2", max_drift_.gamma_norm2},
                      {"C0 (area)", max_drift_.area},
                      {"C1 (energy)", max_drift_.energy}};
  if (max_drift_.extra)
    f.overlay.drifts.emplace_back(extra_integral_symbol(run.case_id), *max_drift_.extra);
  return f;
}

}  // namespace epviz::scene
