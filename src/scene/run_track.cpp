#include "scene/run_track.hpp"

#include <algorithm>

#include "scene/plan.hpp"
#include "scene/plane_path.hpp"

namespace epviz::scene {

RunTrack::RunTrack(const sim::RunSpec& spec, View view, int trace_axis, double sphere_px,
                   double plane_px, double px_per_gamma, bool shadowed)
    : spec_(spec),
      view_(view),
      traced_axis_(Eigen::Vector3d::Unit(std::clamp(trace_axis, 1, 3) - 1)),
      trajectory_(sim::Trajectory::start(spec)),
      error_scale_px_(px_per_gamma * shadow_error_factor(spec)),
      drifts_(spec),
      history_(sphere_px, plane_px) {
  trajectory_->observe_steps([this](const sim::Sample& s) { drifts_.step(s); });
  if (shadowed) shadow_ = sim::Trajectory::start(shadow_run(spec));
  take(trajectory_->initial());
}

Eigen::Vector3d RunTrack::on_sphere(const sim::Sample& s) const {
  return view_ == View::space && s.attitude ? Eigen::Vector3d(*s.attitude * traced_axis_) : s.gamma;
}

void RunTrack::run_ahead(const sim::Trajectory::DenseStepObserver& on_step) {
  trajectory_->observe_dense_steps(on_step);
  try {
    for (long k = 1; k <= spec_.samples; ++k) {
      sim::Sample s = trajectory_->next();
      ahead_.push_back({std::move(s), drifts_.drifts().steps});
    }
  } catch (const numerics::IntegrationError& e) {
    ahead_failure_ = e.failure();
  } catch (...) {
    trajectory_->observe_dense_steps(nullptr);
    throw;
  }
  trajectory_->observe_dense_steps(nullptr);  // `on_step` need not outlive this call
  ahead_step_drifts_ = drifts_.drifts().steps;
}

sim::Sample RunTrack::next_sample() {
  if (!ahead_step_drifts_) return trajectory_->next();
  if (ahead_.empty()) {
    if (ahead_failure_) throw numerics::IntegrationError(*ahead_failure_);
    ahead_step_drifts_.reset();  // past the run's end: on as without run_ahead
    return trajectory_->next();
  }
  AheadSample a = std::move(ahead_.front());
  ahead_.pop_front();
  ahead_step_drifts_ = a.step_drifts;
  return a.sample;
}

const sim::Sample& RunTrack::advance() {
  try {
    take(next_sample());
  } catch (const numerics::IntegrationError& e) {
    failure_ = e.failure();
    throw;
  }
  compare_with_shadow(latest_);
  return latest_;
}

void RunTrack::take(const sim::Sample& s) {
  latest_ = s;
  drifts_.output(s);
  drifts_shown_.output = drifts_.drifts().output;
  drifts_shown_.steps = ahead_step_drifts_ ? *ahead_step_drifts_ : drifts_.drifts().steps;
  HistoryPoint p;
  p.t = s.t;
  p.sphere = on_sphere(s).cast<float>();
  p.plane = plane_point(s.gamma);
  p.gamma3 = float(s.gamma.z());
  history_.offer(p);
}

void RunTrack::compare_with_shadow(const sim::Sample& s) {
  if (!shadow_) return;
  double d = 0.0;
  try {
    const sim::Sample t = shadow_->next();
    // gamma moves both the sphere's point and the plane's; in the space view
    // the sphere shows the apex, whose error counts too.
    d = (s.gamma - t.gamma).norm();
    if (view_ == View::space) d = std::max(d, (on_sphere(s) - on_sphere(t)).norm());
  } catch (const numerics::IntegrationError&) {
    // The estimate ends here; the run itself goes on. From now on nothing is
    // known, so the picture is not claimed to be true beyond this time.
    shadow_.reset();
    shadow_failed_ = true;
    if (!pixel_true_until_) pixel_true_until_ = s.t;
    return;
  }
  const double px = d * error_scale_px_;
  max_error_px_ = std::max(max_error_px_, px);
  if (px > 0.5 && !pixel_true_until_)
    pixel_true_until_ = std::max(0.0, s.t - trajectory_->spacing());
}

}  // namespace epviz::scene
