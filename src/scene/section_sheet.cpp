#include "scene/section_sheet.hpp"

#include "sim/section_chart_inverse.hpp"

namespace epviz::scene {

std::optional<SectionSheet> default_sheet(const sim::SectionSurface& surface,
                                          const std::array<sim::StateComponent, 2>& coords) {
  if (auto c = sim::chart_sheet_component(surface, coords)) return SectionSheet{*c, 1};
  return std::nullopt;
}

std::string sheet_name(const SectionSheet& sheet) {
  return std::string(sim::symbol(sheet.component)) + (sheet.sign > 0 ? " > 0" : " < 0");
}

bool on_sheet(const std::optional<SectionSheet>& sheet, const physics::Vector3d& omega,
              const physics::Vector3d& gamma) {
  return !sheet || sheet->sign * sim::value_of(sheet->component, omega, gamma) >= 0.0;
}

}  // namespace epviz::scene
