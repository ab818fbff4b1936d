#include "scene/frame_source.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "physics/format.hpp"
#include "physics/notation.hpp"
#include "scene/body_shape.hpp"
#include "scene/cloud_run.hpp"
#include "scene/plane_path.hpp"
#include "scene/run_palette.hpp"
#include "scene/theme.hpp"
#include "sim/section.hpp"

namespace epviz::scene {
namespace {

std::string fmt3(const Eigen::Vector3d& v) { return physics::detail::vec(v, 4); }

}  // namespace

std::string case_title(physics::Case c) {
  return c == physics::Case::custom ? "Heavy top" : std::string(physics::preset(c).title);
}

std::string extra_integral_symbol(physics::Case c) {
  return std::string(physics::integral_symbol(c));
}

int overlay_drift_rows(const sim::RunSpec& run) {
  return 3 + (sim::InvariantMonitor(run.body, run.case_id, run.initial).no_drift().extra ? 1 : 0);
}

int overlay_drift_rows(const std::vector<sim::RunSpec>& runs) {
  if (runs.size() == 1) return overlay_drift_rows(runs.front());
  return int(runs.size());  // one per run: its largest drift
}

std::pair<std::string, double> largest_drift(const sim::Drifts& d, physics::Case c) {
  std::pair<std::string, double> worst{std::string(physics::symbol::gamma_norm2), d.gamma_norm2};
  auto consider = [&](std::string name, double value) {
    // A drift that is not a number is the worst there is.
    if (std::isnan(worst.second)) return;
    if (std::isnan(value) || value > worst.second) worst = {std::move(name), value};
  };
  consider(std::string(physics::symbol::area), d.area);
  consider(std::string(physics::symbol::energy), d.energy);
  if (d.extra) consider(extra_integral_symbol(c), *d.extra);
  return worst;
}

std::string run_legend(const std::string& label, const sim::RunSpec& run,
                       const std::string& accuracy_note, bool with_formulation) {
  std::string s = label.empty() ? "" : label + ": ";
  s += std::string(sim::name(run.method)) + ", " + accuracy_note;
  if (with_formulation) s += ", " + std::string(sim::name(run.formulation));
  return s;
}

std::string pixel_true_note(double until, const sim::RunSpec& run, int width, int height) {
  // An error-controlled run that still parts from its shadow does so because
  // the motion amplifies every small error; a fixed step's error is its own.
  // The horizon is of this picture's pixels: a larger one has an earlier one.
  char line[160];
  std::snprintf(line, sizeof line, "beyond t = %.3g: not pixel-accurate at %d×%d (%s)", until,
                width, height, sim::is_adaptive(run.method) ? "chaos" : "step too coarse");
  return line;
}

FrameSource::FrameSource(const ScenePlan& plan, const SceneSettings& settings)
    : plan_(plan), settings_(settings), shape_(body_shape(plan.run.body)) {
  // The shadow runs estimate the drawn error for the report and the overlay;
  // an open-ended (interactive) scene has no run to report on.
  const bool shadowed = plan.shadow && !plan.open_ended;
  const double ppg = pixels_per_gamma(plan.layout, settings.plane_extent);
  auto add = [&](const sim::RunSpec& spec) {
    tracks_.push_back(std::make_unique<RunTrack>(spec, settings.view, settings.trace_axis,
                                                 plan.trail_sphere_px, plan.trail_plane_px, ppg,
                                                 shadowed));
  };
  add(plan.run);
  for (const auto& other : plan.others) add(other.run);
  separation_.resize(plan.others.size());
  // The cloud: integrated to every frame time at once (renders only: an
  // open-ended scene has no last frame).
  if (settings.cloud.enabled() && !plan.open_ended) {
    cloud_ = std::make_unique<CloudRun>(plan.run, settings.cloud, cloud_times(plan));
  }
}

FrameSource::~FrameSource() = default;

void FrameSource::find_crossings() {
  // The panel's axes take in every crossing of the whole run, so that no dot
  // moves as frames go: each run is integrated to its end before the first
  // frame, once, its crossings found on its own steps as they are taken
  // (sim::SectionObserver), and its samples kept for the frames.
  std::vector<std::vector<sim::Crossing>> crossings;
  for (auto& track : tracks_) {
    sim::SectionObserver section(track->spec(), settings_.section->surface);
    track->run_ahead([&section](const sim::DenseStep& step) { section.step(step); });
    crossings.push_back(section.crossings());
  }
  // The orbits started from the live panel's points, run as the first run.
  for (const auto& start : settings_.section->orbits) {
    SectionOrbit orbit(plan_.run, start, settings_.section->surface);
    orbit.advance_to(plan_.run.t_end, std::numeric_limits<long>::max());
    crossings.push_back(orbit.crossings());
  }
  section_ = std::make_unique<SectionCrossings>(*settings_.section, std::move(crossings));
}

void FrameSource::advance() {
  for (auto& track : tracks_) track->advance();
  ++sample_index_;
  const auto& first = tracks_.front()->latest();
  for (std::size_t i = 1; i < tracks_.size(); ++i) {
    const auto& s = tracks_[i]->latest();
    separation_[i - 1].add(float(s.t), float((s.gamma - first.gamma).norm()));
  }
}

Frame FrameSource::frame(int index) {
  // The section's crossings: found at the first frame, from each run
  // integrated to its end (renders only, as the cloud); a crossing that loses
  // the motion ends the run there, a numerical failure at that frame.
  if (settings_.section && !section_ && !plan_.open_ended) find_crossings();
  const long target = long(index) * plan_.samples_per_frame;
  while (sample_index_ < target) advance();
  for (auto& track : tracks_) track->forget_before(time() - trail_window());
  return compose(index);
}

double FrameSource::trail_window() const {
  return settings_.trail_length > 0.0 ? settings_.trail_length : plan_.run.t_end;
}

Frame FrameSource::frame_at_time(double t) {
  const double spacing = trajectory().spacing();
  // Half a spacing of slack: the sample nearest to t is taken, never one after it.
  while (time() + 0.5 * spacing <= t) advance();
  for (auto& track : tracks_) track->forget_before(time() - trail_window());
  return compose(++frames_composed_);
}

Frame FrameSource::compose(int index) const {
  Frame f;
  const sim::Sample& last = latest();
  f.index = index;
  f.t = last.t;
  f.view = settings_.view;
  f.layers = settings_.layers;
  f.camera = settings_.camera;
  f.theme = settings_.theme;
  f.colours = settings_.colours;
  f.body = shape_;
  f.plane_extent = settings_.plane_extent;
  f.page = settings_.page;

  const double window = trail_window();
  auto age = [&](double t) { return float(std::clamp((last.t - t) / window, 0.0, 1.0)); };

  if (settings_.view == View::space && last.attitude) {
    f.body_rotation = last.attitude->cast<float>();
    f.current = tracks_.front()->on_sphere(last).cast<float>();
    f.trail_label = "body axis " + std::to_string(settings_.trace_axis) + " (space frame)";
  } else {
    f.current = last.gamma.cast<float>();
    f.trail_label = std::string(physics::symbol::gamma) + " (body frame)";
  }
  f.trail_time = window;
  const auto& pts = tracks_.front()->history().points();
  f.trail.reserve(pts.size() + 1);
  for (const auto& p : pts) f.trail.push_back({p.sphere, age(p.t)});
  f.trail.push_back({f.current, 0.0f});

  auto path = build_plane_path(pts, f.plane_extent, age);
  f.plane_path = std::move(path.points);
  f.plane_marks = std::move(path.marks);
  if (auto ab = plane_point(last.gamma)) {
    const Eigen::Vector2f now = *ab;
    f.plane_path.push_back({now, 0.0f, false});
    if (inside_panel(now, f.plane_extent)) f.plane_current = now;
  }

  if (cloud_ && index < cloud_->frame_count()) {
    f.cloud = cloud_->frame(index, f.plane_extent);
    if (settings_.view == View::space) f.cloud->sphere.clear();  // its points are body-frame gamma
  }

  if (section_) {
    const bool light = is_light(settings_.colours.background);
    std::vector<Rgba> colours;
    for (int i = 0; i < run_count(); ++i) colours.push_back(run_colour(i, light));
    f.section = section_->panel_at(last.t, colours, light);
  }

  const auto& run = plan_.run;
  f.overlay.title = settings_.title.empty() ? case_title(run.case_id) : settings_.title;
  // Most important first: a small picture shows only the first lines.
  char line[160];
  if (plan_.open_ended)
    std::snprintf(line, sizeof line, "t = %.3f", last.t);
  else
    std::snprintf(line, sizeof line, "t = %.3f / %g", last.t, run.t_end);
  f.overlay.lines.emplace_back(line);
  f.overlay.lines.push_back(std::string(sim::name(run.method)) + ", " + plan_.accuracy_note);
  f.overlay.lines.push_back(std::string(sim::name(run.formulation)) + " formulation");
  std::snprintf(line, sizeof line, "I = %s", fmt3(run.body.inertia).c_str());
  f.overlay.lines.emplace_back(line);
  std::snprintf(line, sizeof line, "r = %s   P = %.4g", fmt3(run.body.com).c_str(),
                run.body.weight);
  f.overlay.lines.emplace_back(line);
  assert(int(f.overlay.lines.size()) == kOverlayLines);
  const sim::Drifts& drift = max_drift();
  if (const auto& until = tracks_.front()->pixel_true_until()) {
    f.pixel_true_until = *until;
    f.untrue_age = age(*until);
    f.pixel_true_note = pixel_true_note(*until, run, settings_.width, settings_.height);
  }
  if (plan_.comparison()) {
    compose_comparison(f);
    return f;
  }
  f.overlay.drifts = {{std::string(physics::symbol::gamma_norm2), drift.gamma_norm2},
                      {std::string(physics::symbol::area) + " (area)", drift.area},
                      {std::string(physics::symbol::energy) + " (energy)", drift.energy}};
  if (drift.extra) f.overlay.drifts.emplace_back(extra_integral_symbol(run.case_id), *drift.extra);
  return f;
}

std::vector<double> FrameSource::step_drift_column() const {
  const sim::Drifts& steps = tracks_.front()->drifts().steps;
  std::vector<double> column{steps.gamma_norm2, steps.area, steps.energy};
  if (steps.extra) column.push_back(*steps.extra);
  return column;
}

void FrameSource::compose_comparison(Frame& f) const {
  const double window = trail_window();
  const double now = time();
  auto age = [&](double t) { return float(std::clamp((now - t) / window, 0.0, 1.0)); };
  Comparison c;
  c.t_end = plan_.run.t_end;
  bool formulations_differ = false;
  for (const auto& o : plan_.others)
    formulations_differ |= o.run.formulation != plan_.run.formulation;
  const bool light = is_light(settings_.colours.background);
  for (int i = 0; i < run_count(); ++i) {
    const auto& track = run(i);
    const std::string& label = i == 0 ? plan_.label : plan_.others[std::size_t(i - 1)].label;
    const std::string& note =
        i == 0 ? plan_.accuracy_note : plan_.others[std::size_t(i - 1)].accuracy_note;
    c.labels.push_back(run_legend(label, track.spec(), note, formulations_differ));
    c.colours.push_back(run_colour(i, light));
    c.lines.push_back(run_line_style(i));
    // Each run's largest drift, named: the one that says most of its accuracy.
    auto [name, value] = largest_drift(track.drifts().output, track.spec().case_id);
    f.overlay.drifts.emplace_back(std::to_string(i + 1) + ": " + name, value);
    if (i == 0) continue;

    RunTrace r;
    const auto& latest = track.latest();
    r.current = track.on_sphere(latest).cast<float>();
    const auto& pts = track.history().points();
    r.trail.reserve(pts.size() + 1);
    for (const auto& p : pts) r.trail.push_back({p.sphere, age(p.t)});
    r.trail.push_back({r.current, 0.0f});
    auto path = build_plane_path(pts, f.plane_extent, age);
    r.plane_path = std::move(path.points);
    r.plane_marks = std::move(path.marks);
    if (auto ab = plane_point(latest.gamma)) {
      const Eigen::Vector2f p = *ab;
      r.plane_path.push_back({p, 0.0f, false});
      if (inside_panel(p, f.plane_extent)) r.plane_current = p;
    }
    r.separation = separation_[std::size_t(i - 1)].points();
    if (const auto& until = track.pixel_true_until()) {
      r.pixel_true_until = *until;
      r.untrue_age = age(*until);
    }
    c.others.push_back(std::move(r));
  }
  f.comparison = std::move(c);
}

}  // namespace epviz::scene
