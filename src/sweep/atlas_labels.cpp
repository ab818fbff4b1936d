#include "sweep/atlas_labels.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io/number_text.hpp"
#include "physics/cases.hpp"
#include "physics/notation.hpp"
#include "sim/section.hpp"
#include "sweep/level_point.hpp"

namespace epviz::sweep {
namespace {

using Json = nlohmann::json;

// The component index of "name[k]", or -1.
int component(const std::string& field, const std::string& name) {
  if (field.size() != name.size() + 3 || !field.starts_with(name + "[") || field.back() != ']')
    return -1;
  const char k = field[name.size() + 1];
  return k >= '0' && k <= '2' ? k - '0' : -1;
}

// The value of `key` that every row has alike; nullopt when one lacks it or differs.
std::optional<Json> shared(const std::vector<const Json*>& rows, const std::string& key) {
  std::optional<Json> v;
  for (const Json* r : rows) {
    if (!r->contains(key) || (*r)[key].is_null()) return std::nullopt;
    if (v && *v != (*r)[key]) return std::nullopt;
    v = (*r)[key];
  }
  return v;
}

// The fourth integral's symbol from the case table when every row ran the same
// case and that case has one ("K", "Ω₃"); words that name no case when the
// rows do not say it, ran several, or ran one without a fourth integral.
std::string fourth_integral(const std::vector<const Json*>& rows) {
  if (const auto name = shared(rows, "case"); name && name->is_string())
    if (const auto c = physics::case_from_name(name->get<std::string>()))
      if (const std::string_view s = physics::integral_symbol(*c); !s.empty())
        return std::string(s);
  return "the case's fourth integral";
}

}  // namespace

std::string axis_symbol(const std::string& field) {
  if (const int k = component(field, "omega"); k >= 0)
    return std::string(sim::symbol(sim::StateComponent(int(sim::StateComponent::omega1) + k)));
  if (const int k = component(field, "gamma"); k >= 0)
    return std::string(sim::symbol(sim::StateComponent(int(sim::StateComponent::gamma1) + k)));
  if (field == "energy") return std::string(physics::symbol::energy);
  if (field == "area_constant") return std::string(physics::symbol::area);
  if (field == "t_end") return "T";
  return field;
}

std::string axis_title(const std::string& field, const std::vector<const Json*>& rows) {
  if (field == "energy") return "energy " + std::string(physics::symbol::energy);
  if (field == "area_constant") return "area constant " + std::string(physics::symbol::area);
  if (field == "t_end") return "end time T";
  const int k = component(field, "gamma");
  if (k < 0) return axis_symbol(field);
  for (const Json* r : rows) {
    const Json& given = (*r)["axes"][field];
    if (!given.is_number() || !r->contains("initial")) continue;
    const double a = given.get<double>(), run = (*r)["initial"]["gamma"][k].get<double>();
    if (std::abs(a - run) > 1e-12 * std::max(1.0, std::abs(a)))
      return axis_symbol(field) + " before normalisation";
  }
  return axis_symbol(field);
}

std::string metric_label(const std::string& metric, const std::vector<const Json*>& rows) {
  if (metric == "ftle") return "largest FTLE λ (1/time)";
  if (metric == "time_to_failure") return "time to failure (time)";
  if (metric == "cpu_seconds") return "CPU time (s)";
  if (metric == "chaotic_share")
    return "share of chaotic orbits (FTLE > " + io::number_text(kChaoticFtle, 4) + ")";
  if (metric == "extra_integral_range")
    return "largest relative range of " + fourth_integral(rows) + " over an orbit";
  if (metric == "reference_error") return "largest distance from the reference run";
  const std::string drift = "max_relative_drift.";
  if (metric.starts_with(drift)) {
    const std::string of = metric.substr(drift.size());
    const std::string symbol = of == "energy"        ? std::string(physics::symbol::energy)
                               : of == "area"        ? std::string(physics::symbol::area)
                               : of == "gamma_norm2" ? std::string(physics::symbol::gamma_norm2)
                                                     : of;
    return "largest relative drift of " + symbol;
  }
  const std::string stable = "largest_stable:";
  if (metric.starts_with(stable))
    return "largest stable " + axis_symbol(metric.substr(stable.size()));
  return metric;
}

std::string atlas_caption(const std::vector<const Json*>& rows, const std::string& metric,
                          const std::optional<FtleSettings>& ftle) {
  std::string run;
  auto add = [&](const std::string& part) { run += (run.empty() ? "" : ", ") + part; };
  if (const auto t = shared(rows, "t_end"); t && t->is_number()) {
    add("T = " + io::number_text(t->get<double>(), 4));
  } else {  // an axis varies it: its range, so that T is never left unsaid
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (const Json* r : rows)
      if (r->contains("t_end") && (*r)["t_end"].is_number()) {
        lo = std::min(lo, (*r)["t_end"].get<double>());
        hi = std::max(hi, (*r)["t_end"].get<double>());
      }
    if (hi >= lo) add("T = " + io::number_text(lo, 4) + " to " + io::number_text(hi, 4));
  }
  if (const auto m = shared(rows, "method"); m && m->is_string())
    add("method " + m->get<std::string>());
  for (const char* key : {"tol", "step"})
    if (const auto v = shared(rows, key); v && v->is_number())
      add(std::string(key) + " = " + io::number_text(v->get<double>(), 4));
  auto part = [&](const std::string& p) { run += (run.empty() ? "" : "; ") + p; };
  if (metric == "ftle" && ftle) {
    const std::string window =
        ftle->window > 0.0 ? io::number_text(ftle->window, 4) : "the sample spacing";
    part("FTLE window " + window + ", separation " + io::number_text(ftle->separation, 4));
  } else if (metric == "ftle") {
    part("FTLE window unknown (the sweep file is gone or changed)");
  }
  if (metric == "chaotic_share") {
    // Orbits above the threshold that the share does not count as chaos
    // (sweep/level_point.hpp): said, so that a map of zeros is not read as
    // orbits that all kept a small FTLE.
    long hyperbolic = 0, undecided = 0;
    for (const Json* r : rows) {
      if (const auto h = r->find("hyperbolic_orbits"); h != r->end() && h->is_number_integer())
        hyperbolic += h->get<long>();
      if (const auto u = r->find("undecided_orbits"); u != r->end() && u->is_number_integer())
        undecided += u->get<long>();
    }
    const std::string above = "FTLE > " + io::number_text(kChaoticFtle, 4);
    const std::string k = fourth_integral(rows);
    if (hyperbolic > 0)
      part(std::to_string(hyperbolic) + (hyperbolic == 1 ? " orbit" : " orbits") + " with " +
           above + " kept " + k + ": hyperbolic, not chaotic");
    if (undecided > 0)
      part(std::to_string(undecided) + (undecided == 1 ? " orbit" : " orbits") + " with " + above +
           " undecided (" + k + " not kept to " + io::number_text(kKeptIntegral, 2) +
           "), left out of the share");
  }
  return run;
}

}  // namespace epviz::sweep
