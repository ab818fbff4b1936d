#include "sim/run_spec.hpp"

namespace epviz::sim {
namespace {

// The enum values of a table's rows (Method of kMethodTable, ...), in order.
template <class Table, class Key>
std::vector<Key> keys(const Table& table, Key Table::value_type::*key) {
  std::vector<Key> v;
  for (const auto& row : table) v.push_back(row.*key);
  return v;
}

// The row of `table` named `s`, as its enum value.
template <class Table, class Key>
std::optional<Key> key_named(const Table& table, Key Table::value_type::*key, std::string_view s) {
  for (const auto& row : table)
    if (row.name == s) return row.*key;
  return std::nullopt;
}

template <class Key>
std::string joined(const std::vector<Key>& keys, std::string_view sep) {
  std::string out;
  for (auto k : keys) {
    if (!out.empty()) out += sep;
    out += name(k);
  }
  return out;
}

}  // namespace

std::string_view name(Formulation f) { return info(f).name; }
std::string_view name(Method m) { return info(m).name; }

std::optional<Formulation> formulation_from_name(std::string_view s) {
  return key_named(kFormulationTable, &FormulationInfo::formulation, s);
}

std::optional<Method> method_from_name(std::string_view s) {
  return key_named(kMethodTable, &MethodInfo::method, s);
}

const std::vector<Formulation>& all_formulations() {
  static const auto all = keys(kFormulationTable, &FormulationInfo::formulation);
  return all;
}

const std::vector<Method>& all_methods() {
  static const auto all = keys(kMethodTable, &MethodInfo::method);
  return all;
}

std::vector<Method> adaptive_methods() {
  std::vector<Method> v;
  for (const auto& row : kMethodTable)
    if (row.adaptive) v.push_back(row.method);
  return v;
}

bool is_adaptive(Method m) { return info(m).adaptive; }
int order(Method m) { return info(m).order; }

std::string names_joined(const std::vector<Method>& methods, std::string_view sep) {
  return joined(methods, sep);
}

std::string names_joined(const std::vector<Formulation>& formulations, std::string_view sep) {
  return joined(formulations, sep);
}

std::optional<std::string> incompatibility(Method m, Formulation f) {
  if (!info(m).needs_direct || f == Formulation::direct) return std::nullopt;
  return "method " + std::string(name(m)) + " needs formulation direct (" +
         std::string(info(m).why_direct) + "); got formulation " + std::string(name(f));
}

RunSpec preset_run(physics::Case c, Method m, Formulation f, double t_end, int samples) {
  const auto& p = physics::preset(c);
  return body_run(c, p.body, p.initial, m, f, t_end, samples);
}

RunSpec body_run(physics::Case c, const physics::Body& body, const physics::InitialState& initial,
                 Method m, Formulation f, double t_end, int samples) {
  RunSpec s;
  s.case_id = c;
  s.body = body;
  s.initial = initial;
  s.method = m;
  s.formulation = f;
  s.t_end = t_end;
  s.samples = samples;
  return s;
}

}  // namespace epviz::sim
