#include "sim/run_spec.hpp"

namespace epviz::sim {
std::string_view name(Formulation f) { return info(f).name; }
std::string_view name(Method m) { return info(m).name; }

std::optional<Formulation> formulation_from_name(std::string_view s) {
  for (const auto& row : kFormulationTable)
    if (row.name == s) return row.formulation;
  return std::nullopt;
}

std::optional<Method> method_from_name(std::string_view s) {
  for (const auto& row : kMethodTable)
    if (row.name == s) return row.method;
  return std::nullopt;
}

const std::vector<Formulation>& all_formulations() {
  static const std::vector<Formulation> all = [] {
    std::vector<Formulation> v;
    for (const auto& row : kFormulationTable) v.push_back(row.formulation);
    return v;
  }();
  return all;
}

const std::vector<Method>& all_methods() {
  static const std::vector<Method> all = [] {
    std::vector<Method> v;
    for (const auto& row : kMethodTable) v.push_back(row.method);
    return v;
  }();
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
  std::string out;
  for (auto m : methods) {
    if (!out.empty()) out += sep;
    out += name(m);
  }
  return out;
}

std::string names_joined(const std::vector<Formulation>& formulations, std::string_view sep) {
  std::string out;
  for (auto f : formulations) {
    if (!out.empty()) out += sep;
    out += name(f);
  }
  return out;
}

std::optional<std::string> incompatibility(Method m, Formulation f) {
  if (!info(m).needs_direct || f == Formulation::direct) return std::nullopt;
  return "method " + std::string(name(m)) + " needs formulation direct (" + std::string(info(m).why_direct) +
         "); got formulation " + std::string(name(f));
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
