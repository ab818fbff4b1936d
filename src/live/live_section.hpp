#pragma once
// The live mode's section panel: the crossings of the runs playing, found on
// the steps they take anyway (a sim::SectionObserver on each run's
// trajectory, so nothing is integrated twice), and of the orbits a click on
// the panel started (scene::SectionOrbit), each brought up to the scene's
// time a bounded number of steps a frame. The panel is drawn by the render
// job's code (scene::section_panel, paint::draw_section_panel), on the axes
// of the whole level (scene::level_range), so that every point a click can
// start an orbit from shows before any crossing is known.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "physics/level_set.hpp"
#include "scene/frame_source.hpp"
#include "scene/section_panel.hpp"

namespace epviz::live {

class LiveSection {
 public:
  // Follows every run of `source` from its next step on; `source` must
  // outlive this object (which stops following it when destroyed).
  LiveSection(const scene::SectionPanelSettings& settings, scene::FrameSource& source);
  ~LiveSection();
  LiveSection(const LiveSection&) = delete;
  LiveSection& operator=(const LiveSection&) = delete;

  const scene::SectionPanelSettings& settings() const { return settings_; }
  const physics::Level& level() const { return level_; }
  // Whether a click can start an orbit (the chart is one
  // sim/section_chart_inverse.hpp inverts), and if not, why.
  std::optional<std::string> clicks_refused() const;

  // An orbit through the panel's point (x, y) on the first run's level, on
  // the sheet `sheet` (+1 or -1: the sign of the component the chart leaves
  // out; the control panel passes the sheet drawn). Returns the notice to
  // show: the orbit's start, or why none was started (no state there, none
  // on this sheet but on the other, orbits at their limit, a chart it
  // cannot invert).
  struct Added {
    bool added = false;
    std::string notice;
  };
  Added add_orbit(double x, double y, int sheet);
  // The sheet drawn (settings().sheet): its crossings shown, the other's counted.
  void set_sheet(const std::optional<scene::SectionSheet>& sheet);
  void clear_orbits();
  int orbit_count() const { return int(orbits_.size()); }
  const scene::SectionOrbit& orbit(int i) const { return *orbits_[std::size_t(i)]; }

  // Brings the orbits towards time `t` with at most `max_steps` steps in all.
  void catch_up(double t, long max_steps);
  // Whether an orbit has yet to reach `t` (frames are still wanted).
  bool behind(double t) const;
  // Failures of orbits not yet reported, as notices (each once).
  std::vector<std::string> take_failures();

  // Crossings so far: each run's, then each orbit's.
  const std::vector<sim::Crossing>& run_crossings(int run) const;
  // The panel at the scene's time `t` (the orbits' crossings up to theirs).
  scene::SectionPanel panel(double t, bool light_background) const;

 private:
  scene::SectionPanelSettings settings_;
  scene::FrameSource& source_;
  sim::RunSpec orbit_run_;  // the first run's spec: what the orbits run as
  physics::Level level_;
  std::array<double, 4> range_;
  std::vector<std::unique_ptr<sim::SectionObserver>> runs_;
  std::vector<std::unique_ptr<scene::SectionOrbit>> orbits_;
  std::vector<bool> failure_told_;
};

}  // namespace epviz::live
