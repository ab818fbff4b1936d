#pragma once
// The regions of a bifurcation diagram (docs/diagram.md, "Sections of each
// region"): the connected parts of the level's image that the attained
// critical curves cut it into, each with one interior point (C1, integral)
// whose Liouville tori `epviz diagram --sections` draws as a Poincaré section.
#include <string>
#include <vector>

#include "physics/critical_values.hpp"

namespace epviz::app {

struct DiagramRegion {
  std::string label;          // "A", "B", ... by the point's energy, then integral
  physics::ValuePoint point;  // the interior point chosen (see diagram_regions)
  // The point's distance to the nearest critical curve or edge of the region,
  // in the chart's spans (energy_max - energy_min across, the sampled
  // integrals' range up).
  double clearance = 0.0;
  std::size_t samples = 0;  // sampled values of the diagram that lie in the region
};

// A region holding fewer sampled values than this is not reported: a sliver
// that thin is not resolved by the sampling (and may be the gap between a
// curve and its chord).
inline constexpr std::size_t kMinRegionSamples = 10;

// The regions, found by a sweep over `columns` energies from energy_min to
// energy_max: on each energy the drawn curves cut the integral's axis into
// intervals; neighbouring energies' intervals join when a path between them
// crosses no curve: a level one through their common range, or the straight
// one from middle to middle (a thin band between two steep curves shares no
// range from one energy to the next). Of the parts
// so joined, those that hold sampled values (each compared with the curves
// at its own energy) are the level's image, the others lie outside it. A
// region's point is the middle of its interval farthest from every curve and
// edge (clearance; an interval open below or above ends at its samples).
// Isolated critical values (Lagrange's sleeping tops) cut nothing.
std::vector<DiagramRegion> diagram_regions(const physics::BifurcationDiagram& diagram,
                                           int columns = 400);

}  // namespace epviz::app
