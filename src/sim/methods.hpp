#pragma once
// Every fact about the integrators and the formulations epviz offers, in one
// table each. Names, orders, step control, the formulation a method needs and
// the help text are read from here by every command, job and sweep. The one
// other spelling of a name is the stepper's own `name` in numerics/, which its
// failure reports carry (numerics knows nothing of this table).
#include <array>
#include <string_view>

namespace epviz::sim {

enum class Formulation { direct, riccati, spinor };
enum class Method {
  rk4,
  dopri5,
  dop853,
  midpoint,
  gauss4,
  gauss6,
  splitting,
  exact_split2,
  exact_split4
};

struct FormulationInfo {
  Formulation formulation;
  std::string_view name;
  int dimension;  // state size integrated
  std::string_view help;
};

struct MethodInfo {
  Method method;
  std::string_view name;
  int order;                    // classical order of the global error
  bool adaptive;                // step chosen by an error estimate (uses tol, dense output)
  bool needs_direct;            // its sub-flows are exact only in the direct formulation
  std::string_view why_direct;  // what those sub-flows are (when needs_direct)
  std::string_view help;
  // The family whose methods drift alike (explicit ones steadily, symplectic
  // ones bounded): the bench's drift chart draws a panel for each.
  std::string_view family;
};

inline constexpr std::array<FormulationInfo, 3> kFormulationTable{{
    {Formulation::direct, "direct", 6, "gamma' = gamma x Omega (6-dimensional)"},
    {Formulation::riccati, "riccati", 5,
     "Ershkov's stereographic (a, b) with a Moebius chart switch at the south pole"},
    {Formulation::spinor, "spinor", 7, "pole-free spinor linearisation, also the body's attitude"},
}};

inline constexpr std::string_view kExplicit = "explicit Runge-Kutta";
inline constexpr std::string_view kGauss = "implicit Gauss-Legendre (symplectic)";
inline constexpr std::string_view kSplittings = "splittings";

inline constexpr std::array<MethodInfo, 9> kMethodTable{{
    {Method::rk4, "rk4", 4, false, false, "", "classical Runge-Kutta, fixed step", kExplicit},
    {Method::dopri5, "dopri5", 5, true, false, "", "Dormand-Prince 5(4), adaptive, dense output",
     kExplicit},
    {Method::dop853, "dop853", 8, true, false, "", "Hairer's DOP853, adaptive, dense output",
     kExplicit},
    {Method::midpoint, "midpoint", 2, false, false, "",
     "implicit midpoint (Gauss 1), fixed step, symplectic", kGauss},
    {Method::gauss4, "gauss4", 4, false, false, "",
     "Gauss-Legendre 2 stages, fixed step, symplectic", kGauss},
    {Method::gauss6, "gauss6", 6, false, false, "",
     "Gauss-Legendre 3 stages, fixed step, symplectic", kGauss},
    {Method::splitting, "splitting", 2, false, true,
     "its sub-flows are exact rotations of (I Omega, gamma)",
     "axis-by-axis Lie-Poisson splitting (Strang), fixed step", kSplittings},
    {Method::exact_split2, "exact-split2", 2, false, true,
     "its sub-flows are the gravity kick and the exact free rigid body flow of (Omega, gamma)",
     "gravity kick + exact free rigid body flow, Strang composition", kSplittings},
    {Method::exact_split4, "exact-split4", 4, false, true,
     "its sub-flows are the gravity kick and the exact free rigid body flow of (Omega, gamma)",
     "gravity kick + exact free rigid body flow, Suzuki 4th-order composition", kSplittings},
}};

// The table's row for a method or formulation (the tables are in enum order).
constexpr const MethodInfo& info(Method m) { return kMethodTable[static_cast<std::size_t>(m)]; }
constexpr const FormulationInfo& info(Formulation f) {
  return kFormulationTable[static_cast<std::size_t>(f)];
}

namespace detail {
constexpr bool tables_in_enum_order() {
  for (std::size_t i = 0; i < kMethodTable.size(); ++i)
    if (static_cast<std::size_t>(kMethodTable[i].method) != i) return false;
  for (std::size_t i = 0; i < kFormulationTable.size(); ++i)
    if (static_cast<std::size_t>(kFormulationTable[i].formulation) != i) return false;
  return true;
}
}  // namespace detail
static_assert(detail::tables_in_enum_order(),
              "method and formulation tables must list the enums in order");

}  // namespace epviz::sim
