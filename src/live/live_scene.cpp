#include "live/live_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "numerics/failure.hpp"
#include "paint/frame_typesetting.hpp"
#include "scene/plan.hpp"
#include "scene/theme.hpp"
#include "sim/failure_advice.hpp"

namespace epviz::live {
namespace {

constexpr double kStepWallSeconds = 1.0 / 30.0;
// Samples per second of wall-clock time at the setup's speed: the trail's
// resolution in time, as in a rendered video (30 frames x 8 samples).
constexpr double kSamplesPerWallSecond = 240.0;
// The run has no end; this many samples make a horizon nobody reaches.
constexpr int kOpenEndedSamples = 100'000'000;
constexpr double kToleranceHorizon = 1e4;
// Trials of an adaptive run's first sample before its spacing is taken as found.
constexpr int kSpacingTrials = 3;
// How quickly pace() follows the frames (the weight of the newest).
constexpr double kPaceWeight = 0.25;

struct SampleCost {
  double spacing;  // at most the one asked for
  double steps;    // one sample's, estimated
};

// The spacing (at most `spacing`) at which one sample of `run` takes about
// LiveScene::kSampleStepLimit steps or fewer. A fixed step says it exactly.
// An adaptive method's first sample is tried with that many steps as its
// limit: one that runs out of them has reached the time it could (the
// failure's), and half of that is tried next, so that no sample the scene
// asks for is unaffordable from the start. Its later steps may be smaller
// (the budget per frame still holds then, a sample at a time).
SampleCost affordable(sim::RunSpec run, double spacing) {
  constexpr long limit = LiveScene::kSampleStepLimit;
  if (!sim::is_adaptive(run.method)) {
    spacing = std::min(spacing, double(limit) * run.step);
    return {spacing, std::max(1.0, std::ceil(spacing / run.step))};
  }
  run.samples = 1;
  run.max_steps = limit;
  for (int trial = 0; trial < kSpacingTrials; ++trial) {
    run.t_end = spacing;
    auto first = sim::Trajectory::start(run);
    try {
      first->next();
      const numerics::Stats st = first->stats();
      return {spacing, std::max(1.0, double(st.steps + st.rejected_steps))};
    } catch (const numerics::IntegrationError& e) {
      // Another failure is the run's own: it reports it when it gets there.
      if (e.failure().kind != numerics::FailureKind::step_budget) break;
      const double reached = e.failure().t;
      spacing = reached > 0.0 && reached < spacing ? 0.5 * reached : spacing / 64.0;
    }
  }
  return {spacing, double(limit)};
}

}  // namespace

std::unique_ptr<scene::FrameSource> LiveScene::make_source(const LiveSetup& setup,
                                                           double& steps_per_sample) {
  std::vector<scene::RunRequest> runs = run_requests(setup);
  for (auto& r : runs) {
    // The automatic tolerance keeps the drawn error under a pixel up to a
    // horizon; a live run has no end, so the horizon is long (the cost of a
    // tighter tolerance is nothing next to drawing a frame).
    r.run.t_end = std::max(r.run.t_end, kToleranceHorizon);
    // The panels have no control for the drift limit and a saved job does not
    // carry one: the live run stops where a render of its saved job would.
    r.run.max_drift = sim::kDefaultMaxDrift;
  }
  scene::ScenePlan plan = scene::plan_scene(std::move(runs), setup.scene, scene::Horizon::none);
  plan.open_ended = true;
  // Every run to the same sample times, as in a render: spaced for the
  // speed, or closer where a run's sample would cost too many steps.
  double spacing = std::max(setup.speed, 1e-3) / kSamplesPerWallSecond;
  std::vector<SampleCost> costs;
  costs.push_back(affordable(plan.run, spacing));
  for (const auto& other : plan.others) costs.push_back(affordable(other.run, spacing));
  for (const SampleCost& c : costs) spacing = std::min(spacing, c.spacing);
  // A run tried at a wider spacing than the one chosen takes fewer steps a
  // sample there (about in proportion; each at least one).
  steps_per_sample = 0.0;
  for (const SampleCost& c : costs)
    steps_per_sample += std::max(1.0, std::ceil(c.steps * spacing / c.spacing));
  auto open_ended = [&](sim::RunSpec& run) {
    run.samples = kOpenEndedSamples;
    run.t_end = spacing * kOpenEndedSamples;
    // The budget per frame bounds the work; a run with no end has no total.
    run.max_steps = std::numeric_limits<long>::max();
  };
  open_ended(plan.run);
  for (auto& other : plan.others) open_ended(other.run);
  return std::make_unique<scene::FrameSource>(plan, setup.scene);
}

LiveScene::LiveScene(const LiveSetup& setup) { restart(setup); }

void LiveScene::restart(const LiveSetup& setup) {
  double steps_per_sample = 1.0;
  auto source = make_source(setup, steps_per_sample);  // may throw: keep the old scene then
  const auto& run = source->plan().run;
  monitor_ = std::make_unique<sim::InvariantMonitor>(run.body, run.case_id, run.initial);
  section_.reset();  // stops following the old runs before they go
  source_ = std::move(source);
  setup_ = setup;
  follow_section();
  steps_per_sample_ = steps_per_sample;
  pace_ = 1.0;
  failure_.reset();
  drift_history_.clear();
  advance_to(0.0);
}

void LiveScene::set_view(const scene::SceneSettings& s, double speed) {
  setup_.scene.layers = s.layers;
  setup_.scene.camera = s.camera;
  setup_.scene.colours = s.colours;
  setup_.speed = speed;
  show_view_settings();
  // The section panel shown or hidden: its crossings from the next step on.
  if (s.section.has_value() != setup_.scene.section.has_value()) {
    setup_.scene.section = s.section;
    follow_section();
    fill_section();
  } else if (s.section && s.section->sheet != setup_.scene.section->sheet) {
    // Another sheet drawn: the crossings found so far stay.
    setup_.scene.section->sheet = s.section->sheet;
    section_->set_sheet(s.section->sheet);
    fill_section();
  }
}

void LiveScene::follow_section() {
  section_.reset();
  if (setup_.scene.section)
    section_ = std::make_unique<LiveSection>(*setup_.scene.section, *source_);
}

void LiveScene::fill_section() {
  if (!section_) {
    frame_.section.reset();
    return;
  }
  section_->catch_up(frame_.t, kSectionStepBudget);
  frame_.section = section_->panel(frame_.t, scene::is_light(setup_.scene.colours.background));
}

LiveSection::Added LiveScene::add_section_orbit(double x, double y, int sheet) {
  if (!section_) return {false, "no orbit started: the section panel is not shown"};
  LiveSection::Added added = section_->add_orbit(x, y, sheet);
  if (added.added) {
    setup_.scene.section->orbits = section_->settings().orbits;
    fill_section();
  }
  return added;
}

void LiveScene::clear_section_orbits() {
  if (!section_) return;
  section_->clear_orbits();
  setup_.scene.section->orbits.clear();
  fill_section();
}

std::vector<std::string> LiveScene::take_section_notices() {
  return section_ ? section_->take_failures() : std::vector<std::string>{};
}

void LiveScene::show_view_settings() {
  frame_.layers = setup_.scene.layers;
  frame_.camera = setup_.scene.camera;
  frame_.colours = setup_.scene.colours;
}

const scene::Frame& LiveScene::update(double wall_seconds) {
  if (playing_)
    advance_to(frame_.t + wall_seconds * setup_.speed);
  else if (section_filling())
    fill_section();  // paused: the clicked orbits still catch up
  return frame_;
}

const scene::Frame& LiveScene::step() {
  advance_to(frame_.t + kStepWallSeconds * setup_.speed);
  return frame_;
}

long LiveScene::steps_taken() const {
  long steps = 0;
  for (int i = 0; i < source_->run_count(); ++i) {
    const numerics::Stats st = source_->run(i).trajectory().stats();
    steps += st.steps + st.rejected_steps;
  }
  return steps;
}

void LiveScene::advance_to(double wanted) {
  if (failure_) return;
  // As many samples as the frame's step budget affords at the last frame's
  // cost per sample, at least one (so that every run moves) and at most
  // kFrameSampleLimit: the frame then ends short of `wanted`, and the run
  // plays slower than its speed.
  const double spacing = source_->trajectory().spacing();
  const double from = source_->time();
  const double samples = std::clamp(std::floor(double(kFrameStepBudget) / steps_per_sample_), 1.0,
                                    double(kFrameSampleLimit));
  const double t = std::min(wanted, from + samples * spacing);
  const long steps_before = steps_taken();
  try {
    frame_ = source_->frame_at_time(t);
    paint::typeset_frame_text(frame_);
  } catch (const numerics::IntegrationError& e) {
    // The last good frame stays on screen with the report; nothing after it
    // is drawn. In a comparison the run that failed is named, in the report
    // and in its legend row, as a render of the same runs stops there too.
    failure_ = sim::failure_line(e.failure(), sim::SettingsIn::panel);
    mark_failed_run();
    playing_ = false;
    return;
  }
  const double taken = std::round((source_->time() - from) / spacing);
  if (taken >= 1.0) steps_per_sample_ = std::max(1.0, double(steps_taken() - steps_before) / taken);
  // A frame the budget cut short reached that share of what it was asked;
  // any other kept up (its sample is the one nearest to the time asked).
  const bool cut_short = t + 0.5 * spacing < wanted;
  const double reached = cut_short ? (source_->time() - from) / (wanted - from) : 1.0;
  if (wanted > from) pace_ += kPaceWeight * (std::clamp(reached, 0.0, 1.0) - pace_);
  show_view_settings();
  show_separation_so_far();
  drift_history_.push_back({frame_.t, monitor_->relative_drift(monitor_->at(source_->latest()))});
  if (drift_history_.size() > kDriftHistory) drift_history_.pop_front();
  fill_section();
}

void LiveScene::mark_failed_run() {
  if (!frame_.comparison) return;
  auto& labels = frame_.comparison->labels;
  for (int i = 0; i < source_->run_count() && std::size_t(i) < labels.size(); ++i) {
    const auto& failure = source_->run(i).failure();
    if (!failure) continue;
    char text[64];
    std::snprintf(text, sizeof text, " - failed at t = %.4g", failure->t);
    labels[std::size_t(i)] += text;
    std::string run = "run ";
    run += std::to_string(i + 1);
    run += ": ";
    *failure_ = run + *failure_;
    return;
  }
}

void LiveScene::show_separation_so_far() {
  if (!frame_.comparison) return;
  // The chart's time axis: from t = 0 to now, as a render of the saved job
  // ends its own at the moment shown (a live run has no end); at least one
  // step's worth, so that the axis at t = 0 has a span to label.
  frame_.comparison->t_end = std::max(frame_.t, kStepWallSeconds * setup_.speed);
}

}  // namespace epviz::live
