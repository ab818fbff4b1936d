#pragma once
// A render job's section panel: the crossings of a section surface by each
// run, found on the run's own steps by the section code's search
// (sim::SectionObserver, FrameSource), and handed to each frame up to its
// time, on axes fixed by all of them.
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "numerics/failure.hpp"
#include "scene/frame.hpp"
#include "scene/section_sheet.hpp"
#include "sim/section.hpp"
#include "sim/trajectory.hpp"

namespace epviz::physics {
struct Level;  // physics/level_set.hpp
}  // namespace epviz::physics

namespace epviz::scene {

// What a job's "section" asks for: the surface, the two coordinates plotted
// and the sheet shown (the keys, defaults and checks of a section file,
// section/section_job.hpp).
struct SectionPanelSettings {
  sim::SectionSurface surface;
  std::array<sim::StateComponent, 2> coords{sim::StateComponent::gamma1,
                                            sim::StateComponent::omega3};
  // Only this sheet's crossings are drawn (the panel counts the others);
  // none: every crossing. default_sheet of the surface and coords above.
  std::optional<SectionSheet> sheet = SectionSheet{};
  // Further orbits, each from its state (on the first run's level, started
  // at a point of the live panel: sim/section_chart_inverse.hpp), run as the
  // first run is (its method, tolerance, formulation, drift limit) over its
  // time; only their crossings are drawn, each orbit in a colour of its own.
  std::vector<physics::InitialState> orbits;
};

// A job's "section" holds at most this many orbits.
inline constexpr int kMaxSectionOrbits = 8;

// The colour of orbit `index` (0 = the first) of a section panel: apart
// from the runs' colours (scene/run_palette.hpp) on either background.
Rgba section_orbit_colour(int index, bool light_background);

// The crossing an orbit started on the surface begins with: its start, at t = 0.
sim::Crossing start_crossing(const physics::InitialState& start);

// One of SectionPanelSettings::orbits as a run of its own: integrated as
// `run` (the first run, its sample times too) from `start`, its crossings of
// `surface` found on its steps as they are taken (sim::SectionObserver),
// its start the first. It goes only as far as asked, so that the live mode
// can spread its integration over frames.
class SectionOrbit {
 public:
  SectionOrbit(sim::RunSpec run, const physics::InitialState& start,
               const sim::SectionSurface& surface);
  ~SectionOrbit();
  SectionOrbit(const SectionOrbit&) = delete;  // its trajectory reports to its observer
  SectionOrbit& operator=(const SectionOrbit&) = delete;

  // Integrates through the samples up to time `t` (never backwards), stopping
  // early once it has taken `max_steps` steps (accepted and rejected) in this
  // call. A numerical failure, or a crossing or sample that loses the motion,
  // ends the orbit there (failure()); its crossings so far stay.
  void advance_to(double t, long max_steps);
  double time() const { return t_; }
  const std::vector<sim::Crossing>& crossings() const { return crossings_; }
  const std::optional<numerics::Failure>& failure() const { return failure_; }
  // Steps taken so far, accepted and rejected.
  long steps() const;

 private:
  void collect();
  std::unique_ptr<sim::SectionObserver> observer_;
  std::unique_ptr<sim::Trajectory> trajectory_;
  std::vector<sim::Crossing> crossings_;
  std::size_t collected_ = 0;  // the observer's crossings already in crossings_
  double t_ = 0.0;
  std::optional<numerics::Failure> failure_;
};

// The plot's range for a level: every state of it lies inside (a gamma
// component in [-1, 1], Omega_j with 1/2 I_j Omega_j^2 <= C1 + P |r|), with
// the panel's margin, so that the whole region an orbit of the level can
// reach, and a click can start one in, shows before any crossing is known.
std::array<double, 4> level_range(const physics::Body& body, const physics::Level& level,
                                  const std::array<sim::StateComponent, 2>& coords);

// The panel of `settings` on `range` with `crossings` (per run or orbit,
// in time order) up to time `t` of each, the i-th in `colours[i]`: those on
// settings.sheet drawn, those on the other sheet counted (SectionPanel::hidden).
SectionPanel section_panel(const SectionPanelSettings& settings, const std::array<double, 4>& range,
                           const std::vector<const std::vector<sim::Crossing>*>& crossings,
                           const std::vector<double>& t, const std::vector<Rgba>& colours);

// "γ₃ = 0, upward": the panel's title; with a sheet "γ₃ = 0, upward, γ₂ > 0".
std::string section_title(const sim::SectionSurface& surface,
                          const std::optional<SectionSheet>& sheet = std::nullopt);

class SectionCrossings {
 public:
  // Every crossing of each run (the runs of a scene: the first, then the
  // others, then settings.orbits' orbits), in time order.
  SectionCrossings(const SectionPanelSettings& settings,
                   std::vector<std::vector<sim::Crossing>> crossings);

  // The panel at time `t`: each run's crossings at or before it, in
  // `colours` (one per run), then the orbits' in their colours.
  SectionPanel panel_at(double t, const std::vector<Rgba>& colours, bool light = false) const;
  const std::vector<std::vector<sim::Crossing>>& crossings() const { return crossings_; }

 private:
  SectionPanelSettings settings_;
  std::vector<std::vector<sim::Crossing>> crossings_;
  std::array<double, 4> range_{-1.0, 1.0, -1.0, 1.0};
};

}  // namespace epviz::scene
