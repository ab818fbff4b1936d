#pragma once
// Which sheet of a section's chart a panel draws: apart from the panel, so
// that the job reader (and its fuzz target) checks a job's "section.sheet"
// without the panel's crossings and drawing.
#include <array>
#include <optional>
#include <string>

#include "sim/section.hpp"

namespace epviz::scene {

// One sheet of a section surface's chart: the states whose `component` has
// the sign `sign` (+1 or -1). The plotted coordinates cover a surface such as
// gamma3 = 0 twice (gamma2 > 0 and gamma2 < 0); a panel drawing both on one
// plane would set orbits of one sheet among those of the other.
struct SectionSheet {
  sim::StateComponent component = sim::StateComponent::gamma2;
  int sign = 1;
  bool operator==(const SectionSheet&) const = default;
};

// The sheet a panel shows where none is asked: the positive one of the
// component that tells the chart's sheets apart (sim::chart_sheet_component),
// or none (every crossing) for a chart that has no such component.
std::optional<SectionSheet> default_sheet(const sim::SectionSurface& surface,
                                          const std::array<sim::StateComponent, 2>& coords);

// "γ₂ > 0".
std::string sheet_name(const SectionSheet& sheet);

// Whether `sheet` (none: every crossing) shows the state (omega, gamma): its
// component of the sheet's sign, or 0 (the fold, where both sheets meet and
// the chart gives both one point).
bool on_sheet(const std::optional<SectionSheet>& sheet, const physics::Vector3d& omega,
              const physics::Vector3d& gamma);

}  // namespace epviz::scene
