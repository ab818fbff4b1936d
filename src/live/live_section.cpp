#include "live/live_section.hpp"

#include <algorithm>
#include <cstdio>

#include "physics/invariants.hpp"
#include "scene/run_palette.hpp"
#include "sim/section_chart_inverse.hpp"

namespace epviz::live {

LiveSection::LiveSection(const scene::SectionPanelSettings& settings, scene::FrameSource& source)
    : settings_(settings), source_(source), orbit_run_(source.plan().run) {
  const auto& run = source.plan().run;
  const auto inv = physics::invariants(run.body, run.case_id, run.initial.omega, run.initial.gamma);
  level_ = {inv.energy, inv.area};
  range_ = scene::level_range(run.body, level_, settings_.coords);
  for (int i = 0; i < source.run_count(); ++i) {
    scene::RunTrack& track = source.run(i);
    runs_.push_back(std::make_unique<sim::SectionObserver>(track.spec(), settings_.surface));
    sim::SectionObserver* observer = runs_.back().get();
    track.trajectory().observe_dense_steps(
        [observer](const sim::DenseStep& step) { observer->step(step); });
  }
  for (const auto& start : settings_.orbits) {
    orbits_.push_back(std::make_unique<scene::SectionOrbit>(orbit_run_, start, settings_.surface));
    failure_told_.push_back(false);
  }
}

LiveSection::~LiveSection() {
  for (int i = 0; i < source_.run_count(); ++i) source_.run(i).trajectory().observe_dense_steps({});
}

std::optional<std::string> LiveSection::clicks_refused() const {
  if (sim::chart_sheet_component(settings_.surface, settings_.coords)) return std::nullopt;
  return "a click starts an orbit only on a section of a gamma component (|value| < 1) plotted "
         "at another gamma component and the omega of the surface's";
}

LiveSection::Added LiveSection::add_orbit(double x, double y, int sheet) {
  if (auto why = clicks_refused()) return {false, "no orbit started: " + *why};
  if (orbit_count() >= scene::kMaxSectionOrbits) {
    char text[120];
    std::snprintf(text, sizeof text,
                  "no orbit started: the panel holds %d orbits at most (Clear orbits makes room)",
                  scene::kMaxSectionOrbits);
    return {false, text};
  }
  const auto& run = source_.plan().run;
  auto pre =
      sim::section_states_at(run.body, level_, settings_.surface, settings_.coords, x, y, sheet);
  const auto sheet_component = *sim::chart_sheet_component(settings_.surface, settings_.coords);
  if (pre.states.empty()) {
    // An orbit of the other sheet would not show on the panel (it draws the
    // asked sheet only): say where one can be started instead.
    const auto other =
        sim::section_states_at(run.body, level_, settings_.surface, settings_.coords, x, y, -sheet);
    if (other.states.empty()) return {false, "no orbit started at this point: " + pre.why_none};
    return {false, "no state on this sheet at that point; try " +
                       scene::sheet_name({sheet_component, -sheet})};
  }
  const physics::InitialState& start = pre.states.front();
  orbits_.push_back(std::make_unique<scene::SectionOrbit>(orbit_run_, start, settings_.surface));
  failure_told_.push_back(false);
  settings_.orbits.push_back(start);
  char text[240];
  std::snprintf(text, sizeof text,
                "orbit %d from %s = %.4g, %s = %.4g (%s = %.4g): Ω = (%.4g, %.4g, %.4g)",
                orbit_count(), std::string(sim::symbol(settings_.coords[0])).c_str(), x,
                std::string(sim::symbol(settings_.coords[1])).c_str(), y,
                std::string(sim::symbol(sheet_component)).c_str(),
                sim::value_of(sheet_component, start.omega, start.gamma), start.omega.x(),
                start.omega.y(), start.omega.z());
  return {true, text};
}

void LiveSection::set_sheet(const std::optional<scene::SectionSheet>& sheet) {
  settings_.sheet = sheet;
}

void LiveSection::clear_orbits() {
  orbits_.clear();
  failure_told_.clear();
  settings_.orbits.clear();
}

void LiveSection::catch_up(double t, long max_steps) {
  // Each orbit an equal share, so that a new one fills in beside the others.
  if (orbits_.empty()) return;
  const long share = std::max(1L, max_steps / long(orbits_.size()));
  for (auto& orbit : orbits_)
    if (!orbit->failure()) orbit->advance_to(t, share);
}

bool LiveSection::behind(double t) const {
  const double half = 0.5 * source_.trajectory().spacing();
  return std::any_of(orbits_.begin(), orbits_.end(),
                     [&](const auto& o) { return !o->failure() && o->time() + half <= t; });
}

std::vector<std::string> LiveSection::take_failures() {
  std::vector<std::string> notices;
  for (std::size_t i = 0; i < orbits_.size(); ++i) {
    if (failure_told_[i] || !orbits_[i]->failure()) continue;
    failure_told_[i] = true;
    char text[240];
    std::snprintf(text, sizeof text, "section orbit %zu stopped at t = %.4g: %s", i + 1,
                  orbits_[i]->failure()->t, orbits_[i]->failure()->message().c_str());
    notices.emplace_back(text);
  }
  return notices;
}

const std::vector<sim::Crossing>& LiveSection::run_crossings(int run) const {
  return runs_[std::size_t(run)]->crossings();
}

scene::SectionPanel LiveSection::panel(double t, bool light) const {
  std::vector<const std::vector<sim::Crossing>*> lists;
  std::vector<double> until;
  std::vector<scene::Rgba> colours;
  for (std::size_t i = 0; i < runs_.size(); ++i) {
    lists.push_back(&runs_[i]->crossings());
    until.push_back(t);
    colours.push_back(scene::run_colour(int(i), light));
  }
  for (std::size_t k = 0; k < orbits_.size(); ++k) {
    lists.push_back(&orbits_[k]->crossings());
    until.push_back(orbits_[k]->time());
    colours.push_back(scene::section_orbit_colour(int(k), light));
  }
  return scene::section_panel(settings_, range_, lists, until, colours);
}

}  // namespace epviz::live
