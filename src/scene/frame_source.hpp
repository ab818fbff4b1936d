#pragma once
// Runs the simulation ahead of the renderer and hands out one scene::Frame per
// frame time, with bounded memory (the trail keeps only what the screen shows).
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "scene/frame.hpp"
#include "scene/plan.hpp"
#include "scene/run_track.hpp"
#include "scene/section_panel.hpp"
#include "scene/separation_history.hpp"
#include "sim/drift.hpp"
#include "sim/trajectory.hpp"

namespace epviz::scene {

// The cloud of a job with a "cloud" (scene/cloud_run.hpp, which brings the
// batch integrator): only frame_source.cpp needs it whole.
class CloudRun;

class FrameSource {
 public:
  FrameSource(const ScenePlan& plan, const SceneSettings& settings);
  ~FrameSource();
  // The trajectory reports its steps to this object: it stays where it was built.

  int frame_count() const { return plan_.frames; }
  // Frame `index`; indices must not decrease (skipped frames are still
  // integrated through). Throws numerics::IntegrationError on a numerical
  // failure, including a sample that lost the motion (sim/drift.hpp): no frame
  // is composed at or after its time.
  Frame frame(int index);
  // Open-ended use (the interactive scene): integrates through every sample up
  // to simulation time `t` (never backwards) and composes the next frame.
  Frame frame_at_time(double t);

  // The first run (the only one outside comparison scenes).
  const sim::Trajectory& trajectory() const { return tracks_.front()->trajectory(); }
  // The drift over the samples drawn (the overlay's), interpolated ones included.
  const sim::Drifts& max_drift() const { return tracks_.front()->drifts().output; }
  // The first run's largest drift at the integrator's own steps so far, in
  // the rows of a single run's overlay drift table (|γ|², C₀, C₁, then the
  // case's integral where it has one).
  std::vector<double> step_drift_column() const;
  const ScenePlan& plan() const { return plan_; }
  double time() const { return latest().t; }
  const sim::Sample& latest() const { return tracks_.front()->latest(); }
  // Every run: the first, then plan().others in order.
  int run_count() const { return int(tracks_.size()); }
  const RunTrack& run(int i) const { return *tracks_[std::size_t(i)]; }
  // The same to follow its steps (the live mode's section panel observes them).
  RunTrack& run(int i) { return *tracks_[std::size_t(i)]; }
  // Each run's crossings of the job's section surface (nullptr without a "section").
  const SectionCrossings* section() const { return section_.get(); }

 private:
  void advance();
  void find_crossings();  // section_, for a job with a "section": runs every track ahead
  Frame compose(int index) const;
  void compose_comparison(Frame& f) const;
  double trail_window() const;  // simulation time the trail covers

  ScenePlan plan_;
  SceneSettings settings_;
  std::vector<std::unique_ptr<RunTrack>> tracks_;
  // Comparison scenes: |delta gamma| of each further run from the first,
  // bounded (a frame copies the points the chart draws, never every sample).
  std::vector<SeparationHistory> separation_;
  long sample_index_ = 0;
  int frames_composed_ = 0;
  BodyShape shape_;
  std::unique_ptr<CloudRun> cloud_;            // renders of jobs with a "cloud" only
  std::unique_ptr<SectionCrossings> section_;  // renders of jobs with a "section" only
};

// The overlay a FrameSource composes has this many text lines, and a drift row
// per invariant it monitors for the run (the plan lays the picture out for it).
// A comparison scene has one row per run: its largest drift.
constexpr int kOverlayLines = 5;
int overlay_drift_rows(const sim::RunSpec& run);
int overlay_drift_rows(const std::vector<sim::RunSpec>& runs);
// The largest relative drift among |γ|², C₀, C₁ and the case's fourth
// integral, with the invariant's overlay name (physics/notation.hpp, "K", ...).
std::pair<std::string, double> largest_drift(const sim::Drifts& drifts, physics::Case c);
// The legend's name of a comparison run: "label: method, accuracy" (the
// formulation added where the runs differ in it).
std::string run_legend(const std::string& label, const sim::RunSpec& run,
                       const std::string& accuracy_note, bool with_formulation);

// The overlay's note on a run's pixel-true horizon `until`.
std::string pixel_true_note(double until, const sim::RunSpec& run);

// "Kovalevskaya top", "Heavy top" for a custom body, ...
std::string case_title(physics::Case c);
// The name of the case's fourth integral on the overlay ("K", "G", ...).
std::string extra_integral_symbol(physics::Case c);

}  // namespace epviz::scene
