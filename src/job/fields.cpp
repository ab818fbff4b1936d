#include "job/fields.hpp"

#include <algorithm>
#include <cstdio>
#include <type_traits>

#include "physics/cases.hpp"
#include "sim/run_spec.hpp"

namespace epviz::job {
namespace {

using SF = SimulationFields;
constexpr double inf = std::numeric_limits<double>::infinity();

FieldInfo field(const char* key, const char* flag, FieldType type, FieldMember m,
                std::string help) {
  FieldInfo f;
  f.key = key;
  f.flag = flag;
  f.type = type;
  f.member = m;
  f.help = std::move(help);
  return f;
}

FieldInfo text(const char* key, const char* flag, FieldOf<std::string> m, std::string dflt,
               std::string help, std::string choices) {
  FieldInfo f = field(key, flag, FieldType::text, m, std::move(help));
  f.default_value = std::move(dflt);
  f.choices = std::move(choices);
  return f;
}

FieldInfo vec(const char* key, const char* flag, FieldOf<std::array<double, 3>> m, double lo,
              double hi, std::string help) {
  FieldInfo f = field(key, flag, FieldType::vec3, m, std::move(help));
  f.min = lo;
  f.max = hi;
  return f;
}

// A number (or an integer, for a member of long) from lo to hi.
template <class T>
FieldInfo number(const char* key, const char* flag, FieldOf<T> m, double lo, double hi,
                 std::string dflt, std::string help) {
  FieldInfo f = field(key, flag, std::is_same_v<T, long> ? FieldType::integer : FieldType::number,
                      m, std::move(help));
  f.min = lo;
  f.max = hi;
  f.default_value = std::move(dflt);
  return f;
}

// A time or a ratio: any positive number.
FieldInfo positive(const char* key, const char* flag, FieldOf<double> m, double dflt,
                   std::string help) {
  FieldInfo f = number<double>(key, flag, m, 0.0, inf, format_number(dflt), std::move(help));
  f.min_exclusive = true;
  return f;
}

// Flags are set on the command line and in a job, but not swept.
FieldInfo flag(const char* key, const char* flag, FieldOf<bool> m, bool sets, std::string help) {
  FieldInfo f = field(key, flag, FieldType::flag, m, std::move(help));
  f.default_value = sets ? "false" : "true";
  f.sweepable = false;
  f.flag_sets = sets;
  return f;
}

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

}  // namespace

bool FieldInfo::in_range(double x) const {
  return (min_exclusive ? x > min : x >= min) && x <= max;
}

std::string FieldInfo::range_text() const {
  const std::string span = "from " + format_number(min) + " to " + format_number(max);
  switch (type) {
    case FieldType::vec3: return "three numbers " + span;
    case FieldType::integer:  // as io::ObjectReader::integer writes it
      return "an integer from " + std::to_string(long(min)) + " to " + std::to_string(long(max));
    case FieldType::number:
      if (min_exclusive && min == 0.0 && max == inf) return "a positive number";
      return "a number " + span;
    case FieldType::text:
    case FieldType::flag: return "";
  }
  return "";
}

std::string format_number(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", value);
  std::string s = buf;
  // "1e+06" -> "1e6", "1e-06" -> "1e-6": as one would write it in a job.
  if (const auto e = s.find('e'); e != std::string::npos) {
    std::string mantissa = s.substr(0, e), exponent = s.substr(e + 1);
    const bool negative = exponent[0] == '-';
    if (exponent[0] == '+' || exponent[0] == '-') exponent.erase(0, 1);
    exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
    s = mantissa + "e" + (negative ? "-" : "") + exponent;
  }
  return s;
}

std::string case_names() {
  std::vector<std::string> names;
  for (const auto& p : physics::case_presets()) names.push_back(p.name);
  return joined(names);
}

const std::vector<FieldInfo>& simulation_field_table() {
  static const sim::RunSpec run;  // the defaults of what a case does not give
  static const std::vector<FieldInfo> table{
      text("case", "--case", &SF::case_name, "",
           "the classical case whose body and state are the defaults; custom or none: a body of "
           "one's own (the generic preset's values for what is not given)",
           case_names() + ", custom"),
      vec("inertia", "--inertia", &SF::inertia, min_moment, max_moment,
          "principal moments I1,I2,I3"),
      vec("com", "--com", &SF::com, -max_magnitude, max_magnitude,
          "centre of mass a0,b0,c0 in body axes"),
      vec("omega", "--omega", &SF::omega, -max_magnitude, max_magnitude,
          "initial angular velocity W1,W2,W3 in body axes"),
      vec("gamma", "--gamma", &SF::gamma, -max_magnitude, max_magnitude,
          "initial vertical G1,G2,G3 in body axes (unit length)"),
      number("weight", "--weight", &SF::weight, -max_magnitude, max_magnitude, "",
             "weight P = m g"),
      number("tol", "--tol", &SF::tol, min_tol, max_tol, format_number(run.tol),
             "relative and absolute tolerance of an adaptive method"),
      positive("step", "--step", &SF::step, run.step, "the step of a fixed-step method"),
      positive("t_end", "--t-end", &SF::t_end, run.t_end, "simulation time of the run"),
      number("samples", "--samples", &SF::samples, 1.0, double(max_samples),
             std::to_string(run.samples), "N: N+1 equally spaced output times from 0 to t_end"),
      text("formulation", "--formulation", &SF::formulation,
           std::string(sim::name(run.formulation)), "the equations integrated",
           sim::names_joined(sim::all_formulations(), ", ")),
      text("method", "--method", &SF::method, std::string(sim::name(run.method)), "the integrator",
           sim::names_joined(sim::all_methods(), ", ")),
      flag("allow_nonphysical", "--allow-nonphysical", &SF::allow_nonphysical, true,
           "accept moments that break the triangle inequalities"),
      flag("normalize_gamma", "--normalize-gamma", &SF::normalize_gamma, true,
           "rescale a non-unit initial gamma to unit length"),
      flag("chart_switch", "--no-chart-switch", &SF::chart_switch, false,
           "riccati: switch charts near the south pole (off: keep the north chart, to show the "
           "pole)"),
      positive("max_drift", "--max-drift", &SF::max_drift, run.max_drift,
               "the run fails (lost the motion) at the first output time whose relative drift of "
               "the energy or of |gamma|^2 exceeds this"),
  };
  return table;
}

const FieldInfo* find_field(std::string_view key) {
  const auto& t = simulation_field_table();
  const auto it =
      std::find_if(t.begin(), t.end(), [&](const FieldInfo& f) { return f.key == key; });
  return it == t.end() ? nullptr : &*it;
}

}  // namespace epviz::job
