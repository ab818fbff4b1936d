#pragma once
// Whether a section's picture folds two sheets of its surface onto one plane.
//
// A surface such as gamma3 = 0 on a level of C0 and C1 is a 2-dimensional
// set, but two plotted coordinates (gamma1, Omega3) cover it twice: the
// coordinates left out (the sign of gamma2, here) tell the two sheets apart.
// Plotted together, an orbit of one sheet lands among the orbits of the
// other and the picture shows intersections and holes that are not there.
// Measured on the crossings themselves: pairs close together in the plot
// whose states are far apart.
#include <array>
#include <vector>

namespace epviz::section {

struct PlottedCrossing {
  double x = 0.0, y = 0.0;        // the plotted coordinates
  std::array<double, 6> state{};  // omega1..3, gamma1..3
};

struct FoldMeasure {
  long close_pairs = 0;  // pairs within kCloseInPlot of each other in the plot
  long far_pairs = 0;    // of those, the pairs farther than kFarInState apart in state
};

// Distances are measured with each coordinate divided by its range over the
// crossings (each plotted axis; Omega and gamma by the widest range of their
// components), so that they compare across sections: close in the plot is
// a 500th of the axes, far in state a fifth of the state's extent. Within
// one sheet a chart maps the first onto at most a few times itself, except
// at the edge where two sheets meet, where the state moves as the square
// root of the plotted distance: sqrt(2 x 2/500), about 0.09, still under a
// fifth.
inline constexpr double kCloseInPlot = 0.002;
inline constexpr double kFarInState = 0.2;

FoldMeasure measure_folds(const std::vector<PlottedCrossing>& crossings);

}  // namespace epviz::section
