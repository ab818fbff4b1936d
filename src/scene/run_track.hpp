#pragma once
// One run of a scene as the frame source follows it: its trajectory, the
// drifts of its steps and of the states it draws, its trail history, and a shadow run that estimates how
// far its picture is from the true motion.
#include <deque>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "numerics/failure.hpp"
#include "scene/frame.hpp"
#include "scene/trail.hpp"
#include "sim/drift.hpp"
#include "sim/trajectory.hpp"

namespace epviz::scene {

class RunTrack {
 public:
  // `trace_axis` (1, 2 or 3): the body axis whose tip the space view traces;
  // `px_per_gamma`: the largest pixels per unit of gamma in the picture
  // (scene::pixels_per_gamma); `shadowed`: follow a shadow run (scene::shadow_run).
  RunTrack(const sim::RunSpec& spec, View view, int trace_axis, double sphere_px, double plane_px,
           double px_per_gamma, bool shadowed);
  RunTrack(const RunTrack&) = delete;  // the trajectory reports its steps to this object
  RunTrack& operator=(const RunTrack&) = delete;

  // Advances to the next sample time. Throws numerics::IntegrationError from
  // the run (a failing shadow only ends the error estimate).
  const sim::Sample& advance();
  // Before the first advance(): integrates the run through its last sample now, each accepted step shown
  // to `on_step` with its dense output, and keeps the samples (with the
  // drift at the steps up to each) for advance() to hand out in turn: a
  // scene that must know the whole run before its first frame (the section
  // panel's fixed axes) integrates it once. The memory is a sample's worth
  // per sample, whatever the steps between them. A failure, the observer's
  // too, ends the run there: advance() throws it on reaching it.
  void run_ahead(const sim::Trajectory::DenseStepObserver& on_step);
  // The run's own failure, once advance() has thrown it (which run of a
  // comparison stopped the scene).
  const std::optional<numerics::Failure>& failure() const { return failure_; }
  void forget_before(double t) { history_.forget_before(t); }

  const sim::RunSpec& spec() const { return spec_; }
  const sim::Trajectory& trajectory() const { return *trajectory_; }
  sim::Trajectory& trajectory() { return *trajectory_; }
  // At the integrator's steps and over the samples drawn (sim::RunDrifts):
  // the picture shows the second.
  const sim::RunDrifts& drifts() const { return drifts_shown_; }
  const sim::Sample& latest() const { return latest_; }
  const TrailHistory& history() const { return history_; }
  // The point drawn on the sphere for a sample (gamma, or the apex in the space view).
  Eigen::Vector3d on_sphere(const sim::Sample& s) const;

  // The last sample time up to which the estimated error of the drawn point
  // stayed within half a pixel, once it has not; empty while it has.
  const std::optional<double>& pixel_true_until() const { return pixel_true_until_; }
  // The largest estimated error so far, in pixels (0 without a shadow).
  double max_error_px() const { return max_error_px_; }
  bool shadowed() const { return shadow_ != nullptr || shadow_failed_; }
  bool shadow_failed() const { return shadow_failed_; }
  const sim::Trajectory* shadow() const { return shadow_.get(); }

 private:
  // A sample integrated ahead, with the largest drift at the steps up to it.
  struct AheadSample {
    sim::Sample sample;
    sim::Drifts step_drifts;
  };
  sim::Sample next_sample();
  void take(const sim::Sample& s);
  void compare_with_shadow(const sim::Sample& s);

  sim::RunSpec spec_;
  View view_;
  Eigen::Vector3d traced_axis_;  // body axes
  std::unique_ptr<sim::Trajectory> trajectory_;
  std::unique_ptr<sim::Trajectory> shadow_;
  bool shadow_failed_ = false;
  double error_scale_px_;  // estimated error in pixels per unit of |run - shadow|
  sim::RunDriftMonitor drifts_;
  sim::RunDrifts drifts_shown_;                     // up to the latest sample handed out
  std::deque<AheadSample> ahead_;                   // run_ahead's samples not handed out yet
  std::optional<numerics::Failure> ahead_failure_;  // what ended run_ahead's run
  std::optional<sim::Drifts> ahead_step_drifts_;    // the latest sample's, once run ahead
  TrailHistory history_;
  sim::Sample latest_;
  std::optional<double> pixel_true_until_;
  double max_error_px_ = 0.0;
  std::optional<numerics::Failure> failure_;
};

}  // namespace epviz::scene
