#pragma once
// A render job's section panel: the crossings of a section surface by each
// run, found on the run's own steps by the section code's search
// (sim::SectionObserver, FrameSource), and handed to each frame up to its
// time, on axes fixed by all of them.
#include <array>
#include <vector>

#include "scene/frame.hpp"
#include "sim/section.hpp"

namespace epviz::scene {

// What a job's "section" asks for: the surface and the two coordinates
// plotted (the keys, defaults and checks of a section file, section/section_job.hpp).
struct SectionPanelSettings {
  sim::SectionSurface surface;
  std::array<sim::StateComponent, 2> coords{sim::StateComponent::gamma1,
                                            sim::StateComponent::omega3};
};

// "γ₃ = 0, upward": the panel's title.
std::string section_title(const sim::SectionSurface& surface);

class SectionCrossings {
 public:
  // Every crossing of each run (the runs of a scene: the first, then the
  // others), in time order.
  SectionCrossings(const SectionPanelSettings& settings,
                   std::vector<std::vector<sim::Crossing>> crossings);

  // The panel at time `t`: each run's crossings at or before it, in `colours` (one per run).
  SectionPanel panel_at(double t, const std::vector<Rgba>& colours) const;
  const std::vector<std::vector<sim::Crossing>>& crossings() const { return crossings_; }

 private:
  SectionPanelSettings settings_;
  std::vector<std::vector<sim::Crossing>> crossings_;
  std::array<double, 4> range_{-1.0, 1.0, -1.0, 1.0};
};

}  // namespace epviz::scene
