#pragma once
// `epviz diagram`'s figure and tables: the bifurcation diagram
// (physics/critical_values.hpp) as a chart for the figure painters, and its
// points as CSV text (docs/diagram.md).
#include <string>

#include "app/diagram_regions.hpp"
#include "chart/chart_spec.hpp"
#include "physics/critical_values.hpp"

namespace epviz::app {

// The chart "diagram.png": the sampled values as small dots, each critical
// curve as a named line over them (single critical values as markers); axes
// C₁ and the case's integral; the title names the case and C₀. Each of
// `regions` (--sections) is a black marker at its point, a shape of its own,
// named in the legend by its label and point.
chart::Figure diagram_figure(const physics::DiagramRequest& request,
                             const physics::BifurcationDiagram& diagram,
                             const std::vector<DiagramRegion>& regions = {});

// "curve,energy,integral" and a row per drawn point of the critical curves,
// curve by curve, in order along each (the breaks between attained parts are
// not rows).
std::string critical_curves_csv(const physics::BifurcationDiagram& diagram);

// "region,energy,integral,clearance,samples" and a row per region: its
// label, point (exact: the level its section's orbits are on), clearance and
// the sampled states in it.
std::string regions_csv(const std::vector<DiagramRegion>& regions);

// "energy,integral" and a row per sampled state.
std::string sampled_values_csv(const physics::BifurcationDiagram& diagram);

}  // namespace epviz::app
