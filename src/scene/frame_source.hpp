#pragma once
// Runs the simulation ahead of the renderer and hands out one scene::Frame per
// frame time, with bounded memory (the trail keeps only what the screen shows).
#include <memory>

#include "scene/frame.hpp"
#include "scene/plan.hpp"
#include "scene/trail.hpp"
#include "sim/drift.hpp"
#include "sim/trajectory.hpp"

namespace epviz::scene {

class FrameSource {
 public:
  FrameSource(const ScenePlan& plan, const SceneSettings& settings);

  int frame_count() const { return plan_.frames; }
  // Frame `index`; indices must not decrease (skipped frames are still
  // integrated through). Throws numerics::IntegrationError on a numerical
  // failure, including a sample that lost the motion (sim/drift.hpp): no frame
  // is composed at or after its time.
  Frame frame(int index);
  // Open-ended use (the interactive scene): integrates through every sample up
  // to simulation time `t` (never backwards) and composes the next frame.
  Frame frame_at_time(double t);

  const sim::Trajectory& trajectory() const { return *trajectory_; }
  const sim::Drifts& max_drift() const { return max_drift_; }
  const ScenePlan& plan() const { return plan_; }
  double time() const { return latest_.t; }
  const sim::Sample& latest() const { return latest_; }

 private:
  void take(const sim::Sample& s);
  Frame compose(int index) const;
  double trail_window() const;          // simulation time the trail covers
  Eigen::Vector3d traced_axis() const;  // space view: the body axis the trail follows

  ScenePlan plan_;
  SceneSettings settings_;
  std::unique_ptr<sim::Trajectory> trajectory_;
  sim::InvariantMonitor monitor_;
  sim::Drifts max_drift_;
  TrailHistory history_;
  sim::Sample latest_;
  long sample_index_ = 0;
  int frames_composed_ = 0;
  BodyShape shape_;
};

// The overlay a FrameSource composes has this many text lines, and a drift row
// per invariant it monitors for the run (the plan lays the picture out for it).
constexpr int kOverlayLines = 5;
int overlay_drift_rows(const sim::RunSpec& run);

// "Kovalevskaya top", "Heavy top" for a custom body, ...
std::string case_title(physics::Case c);
// The name of the case's fourth integral on the overlay ("K", "G", ...).
std::string extra_integral_symbol(physics::Case c);

}  // namespace epviz::scene
