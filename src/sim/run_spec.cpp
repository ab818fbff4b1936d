#include "sim/run_spec.hpp"

#include <array>
#include <utility>

namespace epviz::sim {
namespace {

constexpr std::array<std::pair<Formulation, std::string_view>, 3> kFormulations{{
    {Formulation::direct, "direct"},
    {Formulation::riccati, "riccati"},
    {Formulation::spinor, "spinor"},
}};

constexpr std::array<std::pair<Method, std::string_view>, 9> kMethods{{
    {Method::rk4, "rk4"},
    {Method::dopri5, "dopri5"},
    {Method::dop853, "dop853"},
    {Method::midpoint, "midpoint"},
    {Method::gauss4, "gauss4"},
    {Method::gauss6, "gauss6"},
    {Method::splitting, "splitting"},
    {Method::exact_split2, "exact-split2"},
    {Method::exact_split4, "exact-split4"},
}};

template <class Table, class Key>
std::string_view lookup_name(const Table& table, Key key) {
  for (const auto& [k, n] : table)
    if (k == key) return n;
  return "?";
}

template <class Table>
auto lookup_key(const Table& table, std::string_view s)
    -> std::optional<typename Table::value_type::first_type> {
  for (const auto& [k, n] : table)
    if (n == s) return k;
  return std::nullopt;
}

}  // namespace

std::string_view name(Formulation f) { return lookup_name(kFormulations, f); }
std::string_view name(Method m) { return lookup_name(kMethods, m); }
std::optional<Formulation> formulation_from_name(std::string_view s) { return lookup_key(kFormulations, s); }
std::optional<Method> method_from_name(std::string_view s) { return lookup_key(kMethods, s); }

const std::vector<Formulation>& all_formulations() {
  static const std::vector<Formulation> all{Formulation::direct, Formulation::riccati,
                                            Formulation::spinor};
  return all;
}

const std::vector<Method>& all_methods() {
  static const std::vector<Method> all{Method::rk4,    Method::dopri5, Method::dop853,
                                       Method::midpoint, Method::gauss4, Method::gauss6,
                                       Method::splitting, Method::exact_split2,
                                       Method::exact_split4};
  return all;
}

bool is_adaptive(Method m) { return m == Method::dopri5 || m == Method::dop853; }

std::optional<std::string> incompatibility(Method m, Formulation f) {
  if (m == Method::splitting && f != Formulation::direct)
    return "method splitting needs formulation direct (its sub-flows are exact rotations of "
           "(I Omega, gamma)); got formulation " + std::string(name(f));
  if ((m == Method::exact_split2 || m == Method::exact_split4) && f != Formulation::direct)
    return "method " + std::string(name(m)) +
           " needs formulation direct (its sub-flows are the gravity kick and the exact free "
           "rigid body flow of (Omega, gamma)); got formulation " + std::string(name(f));
  return std::nullopt;
}

RunSpec preset_run(physics::Case c, Method m, Formulation f, double t_end, int samples) {
  const auto& p = physics::preset(c);
  RunSpec s;
  s.case_id = c;
  s.body = p.body;
  s.initial = p.initial;
  s.method = m;
  s.formulation = f;
  s.t_end = t_end;
  s.samples = samples;
  return s;
}

}  // namespace epviz::sim
