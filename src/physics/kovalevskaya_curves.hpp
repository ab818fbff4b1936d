#pragma once
// The Kovalevskaya top's critical values at a fixed area, in closed form and
// clipped to what real states attain (docs/math.md §2.6). For the normalised
// body I = (2, 2, 1), r = (1, 0, 0), P = 1 (ε = 1), with h = C1, ℓ = C0,
// k = K, the candidates are
//   k = 0                                (Appelrot's class I),
//   k = (h − ℓ²/2)²                      (class II),
//   h = s + ℓ²/(4s²), k = 1 − ℓ²/(2s) + ℓ⁴/(16 s⁴), s < 0 and s > 0
//                                        (classes III and IV, one per branch).
#include <vector>

#include "physics/critical_values.hpp"

namespace epviz::physics::kovalevskaya {

// The point of the parametric curve at parameter s (s != 0).
ValuePoint parametric_point(double area, double s);

// The roots s of s³ − h s² + ℓ²/4 = 0, the parameters of the parametric
// curve's points at energy h: the one negative root (every h has one), then
// the positive ones (none below the cusp at s = (ℓ²/2)^(1/3), two above, the
// smaller first). For ℓ = 0 the curve is k = 1 and s = h.
std::vector<double> parametric_roots(double area, double energy);

// The four curves for energies from energy_min to energy_max, each kept only
// where a real critical state attains it (physics/kovalevskaya_critical_states.hpp),
// a NaN point between attained parts. `seed` fixes the random starts.
std::vector<CriticalCurve> critical_curves(double area, double energy_min, double energy_max,
                                           unsigned long long seed);

}  // namespace epviz::physics::kovalevskaya
