// Look-ups in the case table (physics/case_table.cpp): nothing here knows a
// particular case.
#include "physics/cases.hpp"

#include <stdexcept>

namespace epviz::physics {
namespace {

// The table's row for `c`, or nullptr for custom.
const CasePreset* find(Case c) {
  for (const CasePreset& p : case_presets())
    if (p.id == c) return &p;
  return nullptr;
}

}  // namespace

const CasePreset& preset(Case c) {
  if (const CasePreset* p = find(c)) return *p;
  throw std::out_of_range("no preset for case '" + case_name(c) + "'");
}

std::string_view integral_symbol(Case c) {
  const CasePreset* p = find(c);
  return p ? p->integral_symbol : std::string_view();
}

std::string case_name(Case c) {
  const CasePreset* p = find(c);
  return p ? p->name : "custom";
}

std::optional<Case> case_from_name(std::string_view name) {
  if (name == "custom") return Case::custom;
  for (const CasePreset& p : case_presets())
    if (name == p.name || (!p.alias.empty() && name == p.alias)) return p.id;
  return std::nullopt;
}

std::optional<std::string> broken_condition(Case c, const Body& body, const InitialState& initial) {
  const CasePreset* p = find(c);
  if (!p || !p->broken) return std::nullopt;
  if (auto why = p->broken(body, initial)) return p->name + " " + *why;
  return std::nullopt;
}

void fit_to_case(Case c, Moment kept, Body& body, InitialState& initial) {
  const CasePreset* p = find(c);
  if (p && p->fit) p->fit(body, initial, kept);
}

std::optional<IntegralValue> extra_integral_terms(Case c, const Body& body, const Vector3d& omega,
                                                  const Vector3d& gamma) {
  const CasePreset* p = find(c);
  if (!p || !p->integral) return std::nullopt;
  return p->integral(body, omega, gamma);
}

std::optional<double> extra_integral(Case c, const Body& body, const Vector3d& omega,
                                     const Vector3d& gamma) {
  if (auto v = extra_integral_terms(c, body, omega, gamma)) return v->value;
  return std::nullopt;
}

}  // namespace epviz::physics
