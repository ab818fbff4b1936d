#pragma once
// The simulation behind the interactive view: a scene::FrameSource with no
// last frame, advanced by wall-clock time times the speed while playing, and
// stopped (not drawn as garbage) at a numerical failure, whose report stays on
// screen until the user restarts. A run that has lost the motion (its energy
// or |gamma|^2 drift above the default limit, sim/drift.hpp) is such a failure.
// With compared runs (LiveSetup::compared) it is a comparison scene, drawn as
// a render of a job with "runs" draws it; a failure of any run stops it.
//
// One render thread serves every browser tab, so a frame's integration work
// is bounded (kFrameStepBudget): a run too costly for its speed (a tiny
// step, a stiff body) plays slower than asked and says so (pace()), rather
// than holding up the other tabs' frames.
#include <deque>
#include <memory>
#include <optional>
#include <string>

#include "live/live_section.hpp"
#include "live/live_setup.hpp"
#include "scene/frame_source.hpp"
#include "scene/separation_history.hpp"
#include "sim/drift.hpp"

namespace epviz::live {

// The current relative drift of each invariant at one time (for the live plots).
struct DriftPoint {
  double t;
  sim::Drifts drift;
};

class LiveScene {
 public:
  // Throws scene::PlanError or std::invalid_argument for a setup that cannot run.
  explicit LiveScene(const LiveSetup& setup);

  const LiveSetup& setup() const { return setup_; }
  // Starts again from t = 0 with `setup` (throws like the constructor, leaving
  // the running scene as it was).
  void restart(const LiveSetup& setup);
  void restart() { restart(setup_); }
  // View settings that need no new run: layers, camera, trail colours, speed.
  void set_view(const scene::SceneSettings& scene, double speed);

  bool playing() const { return playing_; }
  void set_playing(bool on) { playing_ = on && !failure_; }
  // Advances by `wall_seconds` x speed when playing and composes the frame.
  const scene::Frame& update(double wall_seconds);
  // Advances one frame's worth (1/30 s of wall-clock time at this speed), paused or not.
  const scene::Frame& step();

  const scene::Frame& frame() const { return frame_; }
  double time() const { return frame_.t; }
  // The numerical failure that stopped the run, if any: time, method, what
  // happened and which control to change (sim/failure_advice).
  const std::optional<std::string>& failure() const { return failure_; }
  // The drift at each composed frame, oldest first, at most `kDriftHistory` of them.
  static constexpr std::size_t kDriftHistory = 600;
  const std::deque<DriftPoint>& drift_history() const { return drift_history_; }
  const sim::Drifts& max_drift() const { return source_->max_drift(); }
  const std::string& accuracy_note() const { return source_->plan().accuracy_note; }
  sim::Formulation formulation() const { return source_->plan().run.formulation; }
  // The tolerance the run uses (planned when it started; a view change since does not re-plan it).
  double tolerance() const { return source_->plan().run.tol; }
  // A comparison's separation chart has at most this many points a run: the
  // scene's history thins the samples since t = 0, which grow without end,
  // keeping each stretch's lowest and highest (scene/separation_history.hpp).
  static constexpr std::size_t kChartPoints = scene::SeparationHistory::kMaxPoints;
  // The runs drawn: 1, or 1 + setup().compared.size() in a comparison.
  int run_count() const { return source_->run_count(); }

  // The integrator steps (accepted and rejected, all runs together) that one
  // frame may take: measured 2 ms a frame for RK4, 5 for Gauss 6 and 10 for
  // DOP853 at that many steps (tests/live/client_values_test.cpp, 2 loaded cores).
  static constexpr long kFrameStepBudget = 20'000;
  // The most steps one sample may take: the samples are spaced for it, as
  // far as can be known before the run (a fixed step exactly; an adaptive
  // method by a trial of its first sample).
  static constexpr long kSampleStepLimit = kFrameStepBudget / 4;
  // Samples one frame may take whatever their cost (the trail, drift and
  // chart work per sample): more than a frame at the fastest speed needs.
  static constexpr long kFrameSampleLimit = 64;
  // The share of the speed the run reached over the last frames: 1 while it
  // keeps up, less while the step budget holds it back.
  double pace() const { return pace_; }
  bool keeping_up() const { return pace_ > 0.9; }
  // Simulation time between two samples (the speed's, or less where one
  // sample would take more than kSampleStepLimit steps).
  double sample_spacing() const { return source_->trajectory().spacing(); }
  // Integrator steps (accepted and rejected) of every run since t = 0.
  long steps_taken() const;

  // The section panel (setup().scene.section; live_section.hpp), or nullptr.
  const LiveSection* section() const { return section_.get(); }
  // A click at the panel's point (x, y): an orbit from there on the first
  // run's level, kept in setup().scene.section's orbits (so that a restart
  // and a saved job have it); the notice says which state, or why none.
  LiveSection::Added add_section_orbit(double x, double y, int sheet);
  void clear_section_orbits();
  // Whether a clicked orbit has yet to reach the scene's time: frames are
  // wanted while it fills in, paused or not.
  bool section_filling() const { return section_ && section_->behind(frame_.t); }
  // Clicked orbits that stopped (a numerical failure), each said once.
  std::vector<std::string> take_section_notices();
  // The steps the clicked orbits may take in one frame, all together: half
  // the runs' budget, so that a frame costs at most half as much again.
  static constexpr long kSectionStepBudget = kFrameStepBudget / 2;

 private:
  static std::unique_ptr<scene::FrameSource> make_source(const LiveSetup& setup,
                                                         double& steps_per_sample);
  void advance_to(double t);
  // Comparisons: the run whose failure stopped the scene, in its legend row and the report.
  void mark_failed_run();
  // Comparisons: the separation chart's time axis from t = 0 to now.
  void show_separation_so_far();
  // The view settings live in the setup (they change without a restart).
  void show_view_settings();
  // The section panel for setup_.scene.section, following source_ from now.
  void follow_section();
  // Brings the clicked orbits towards the scene's time and puts the panel in the frame.
  void fill_section();

  LiveSetup setup_;
  std::unique_ptr<scene::FrameSource> source_;
  // After source_, whose runs it follows: destroyed first.
  std::unique_ptr<LiveSection> section_;
  std::unique_ptr<sim::InvariantMonitor> monitor_;
  scene::Frame frame_;
  bool playing_ = false;
  std::optional<std::string> failure_;
  std::deque<DriftPoint> drift_history_;
  double steps_per_sample_ = 1.0;  // estimated, all runs together (the last frame's)
  double pace_ = 1.0;
};

}  // namespace epviz::live
