#pragma once
// The bifurcation diagram of an integrable top at a fixed area constant
// (docs/math.md §2.6, docs/diagram.md): the critical values of the map
// (C1, fourth integral) on the level C0 = area, |γ| = 1 — the values of
// states where the integrals' gradients are dependent — drawn only where
// real states attain them, and the image of sampled states of the level,
// the region those curves bound. Kovalevskaya (integral K) and Lagrange
// (integral Ω3) tops.
#include <optional>
#include <string>
#include <vector>

#include "physics/body.hpp"
#include "physics/cases.hpp"

namespace epviz::physics {

// A value of the map: the energy C1 and the fourth integral.
struct ValuePoint {
  double energy = 0.0;
  double integral = 0.0;
};

struct CriticalCurve {
  std::string id;     // for tables: "class_I", "s_negative", "precession_slow", ...
  std::string label;  // for a legend: the class and the curve's equation
  // In order along the curve, attained parts only: a NaN point separates two
  // parts between which real states do not attain the curve.
  std::vector<ValuePoint> points;
  bool isolated = false;  // single critical values (sleeping tops), not a line
};

struct DiagramRequest {
  Case case_id = Case::kovalevskaya;  // kovalevskaya or lagrange
  Body body;                          // satisfying the case's conditions
  double area = 0.0;                  // C0
  std::optional<double> energy_max;   // default: far enough to show every curve's shape
  int samples = 20000;                // states of the level drawn as the admissible region
  unsigned long long seed = 1;        // fixes the samples and the searches' random starts
};

struct BifurcationDiagram {
  double energy_min = 0.0;  // the least C1 at this area (physics/admissible.hpp)
  double energy_max = 0.0;  // the largest C1 shown
  std::vector<CriticalCurve> curves;
  // (C1, integral) of sampled states of the level with C1 <= energy_max: each
  // orbit is one point, both being conserved.
  std::vector<ValuePoint> sampled;
};

// Checks a request before any work, throwing InvalidInput with the field
// "case" (not kovalevskaya or lagrange), "body" (a body the case does not
// allow, or one with no diagram: Kovalevskaya's P a0 = 0), "area" (not
// finite; for Kovalevskaya, |C0| above 8 I3 √ε, past which the search for
// critical states is not reliable) or "energy_max" (not finite, or below the
// least energy). Returns
// the least energy at this area.
double check_diagram_request(const DiagramRequest& request);

// The diagram; the request must pass check_diagram_request.
BifurcationDiagram bifurcation_diagram(const DiagramRequest& request);

}  // namespace epviz::physics
