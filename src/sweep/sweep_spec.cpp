#include "sweep/sweep_spec.hpp"

#include <algorithm>

#include <cmath>

#include "io/json_reader.hpp"
#include "io/json_text.hpp"
#include "io/printable.hpp"
#include "job/fields.hpp"
#include "job/schema.hpp"
#include "shard/checksum.hpp"

namespace epviz::sweep {
namespace {

using Json = nlohmann::json;

constexpr long max_axis_values = 100'000;

// What an axis's values are, from its field's type; "energy" and a vector's
// component take numbers.
bool is_text_field(const std::string& f) {
  const auto* info = job::find_field(f);
  return info && info->type == job::FieldType::text;
}
bool is_vector_field(const std::string& f) {
  const auto* info = job::find_field(f);
  return info && info->type == job::FieldType::vec3;
}

// Numbers from `from` to `to`, both included, evenly spaced (log: in log10).
std::vector<Json> range_values(io::ObjectReader& r, const std::string& field) {
  if (is_text_field(field) || is_vector_field(field))
    r.fail("from", "a range gives numbers; field '" + field + "' takes a list of \"values\"");
  const auto from = r.number("from");
  const auto to = r.number("to");
  const auto count = r.integer("count", 1, max_axis_values);
  const auto scale = r.choice("scale", {"linear", "log"});
  if (!from) r.fail("from", "missing (a range needs from, to and count)");
  if (!to) r.fail("to", "missing (a range needs from, to and count)");
  if (!count) r.fail("count", "missing (a range needs from, to and count)");
  const bool log = scale && *scale == "log";
  if (log && !(*from > 0.0)) r.fail("from", "a log scale needs a positive number");
  if (log && !(*to > 0.0)) r.fail("to", "a log scale needs a positive number");
  std::vector<Json> out;
  for (long i = 0; i < *count; ++i) {
    const double f = *count == 1 ? 0.0 : double(i) / double(*count - 1);
    // The ends exactly as written, whatever the rounding in between.
    const double v =
        i == 0            ? *from
        : i == *count - 1 ? *to
        : log ? std::pow(10.0, std::log10(*from) + f * (std::log10(*to) - std::log10(*from)))
              : *from + f * (*to - *from);
    out.emplace_back(v);
  }
  return out;
}

Axis read_axis(const Json& value, const std::string& file, std::size_t k) {
  const std::string key = "axes[" + std::to_string(k) + "]";
  if (!value.is_object())
    throw io::BadInput(file + ": key '" + key +
                       "': expected an object {\"field\": ..., \"values\": [...]}, got " +
                       io::describe(value));
  io::ObjectReader r(value, file, key);
  Axis a;
  a.key = key;
  const auto field = r.choice("field", axis_fields());
  if (!field) r.fail("field", "missing (allowed: " + axis_fields_joined() + ")");
  a.field = *field;
  if (r.has("values")) {
    if (r.has("from") || r.has("to") || r.has("count") || r.has("scale"))
      r.fail("values", "give either a list of values or from/to/count/scale, not both");
    const Json* v = r.raw("values");
    if (!v->is_array() || v->empty() || v->size() > std::size_t(max_axis_values))
      r.fail("values", "expected a list of 1 to " + std::to_string(max_axis_values) +
                           " values, got " + io::describe(*v));
    for (std::size_t i = 0; i < v->size(); ++i) {
      const Json& x = (*v)[i];
      const std::string at = "values[" + std::to_string(i) + "]";
      if (is_text_field(a.field) && !x.is_string())
        r.fail(at, "field '" + a.field + "' takes strings, got " + io::describe(x));
      if (is_vector_field(a.field) && !(x.is_array() && x.size() == 3 && x[0].is_number() &&
                                        x[1].is_number() && x[2].is_number()))
        r.fail(at, "field '" + a.field + "' takes arrays of 3 numbers, got " + io::describe(x));
      if (!is_text_field(a.field) && !is_vector_field(a.field) &&
          !(x.is_number() && std::isfinite(x.get<double>())))
        r.fail(at, "field '" + a.field + "' takes finite numbers, got " + io::describe(x));
      a.values.push_back(x);
    }
  } else {
    a.values = range_values(r, a.field);
  }
  r.finish();
  return a;
}

}  // namespace

std::vector<std::string> axis_fields() {
  std::vector<std::string> f, components;
  for (const auto& info : job::simulation_field_table()) {
    if (!info.sweepable) continue;
    f.push_back(info.key);
    if (info.type == job::FieldType::vec3)
      for (int i = 0; i < 3; ++i) components.push_back(info.key + "[" + std::to_string(i) + "]");
  }
  f.emplace_back(energy_axis);
  f.emplace_back(area_axis);
  f.insert(f.end(), components.begin(), components.end());
  return f;
}

std::string axis_fields_joined() {
  std::string s;
  for (const auto& f : axis_fields()) s += (s.empty() ? "" : ", ") + f;
  return s;
}

std::vector<std::string> row_metrics() {
  return {"energy",
          "t_end",
          "tol",
          "step",
          "effective_step",
          "max_relative_drift.gamma_norm2",
          "max_relative_drift.area",
          "max_relative_drift.energy",
          "max_relative_drift.extra_integral",
          "failure.t",
          "final.t",
          "samples_written",
          "steps",
          "rhs_evals",
          "rejected_steps",
          "cpu_seconds"};
}

std::vector<std::string> level_row_metrics() {
  return {"ftle",
          "chaotic_share",
          "hyperbolic_orbits",
          "undecided_orbits",
          "extra_integral_range",
          "minimum_energy",
          "lost_orbits",
          "cpu_seconds"};
}

std::string atlas_metrics_allowed(bool reference, bool ftle, const std::vector<std::string>& axes) {
  std::string s;
  auto add = [&](const std::string& m) { s += (s.empty() ? "" : ", ") + m; };
  if (ftle) add("ftle");
  if (reference) add("reference_error");
  add("time_to_failure");
  std::string names;
  for (const auto& a : axes) names += (names.empty() ? "" : ", ") + a;
  add("largest_stable:AXIS (AXIS: " + names + ")");
  for (const auto& m : row_metrics()) add(m);
  return s;
}

namespace {

// Whether the rows of a sweep will hold `metric` (an atlas that draws one
// they lack would only be refused by merge, after every point has run).
bool metric_in_rows(const std::string& metric, bool reference, bool ftle,
                    const std::vector<std::string>& axes, bool levels) {
  if (levels) {
    const auto known = level_row_metrics();
    return std::find(known.begin(), known.end(), metric) != known.end();
  }
  if (metric == "ftle") return ftle;
  if (metric == "reference_error") return reference;
  if (metric == "time_to_failure") return true;
  const std::string stable = "largest_stable:";
  if (metric.starts_with(stable))
    return std::find(axes.begin(), axes.end(), metric.substr(stable.size())) != axes.end();
  const auto known = row_metrics();
  return std::find(known.begin(), known.end(), metric) != known.end();
}

// An energy-momentum map: "level_orbits" with an "energy" and an
// "area_constant" axis, an FTLE, and no axis or reference that would
// contradict the states the level gives.
void check_levels(io::ObjectReader& r, const SweepSpec& s) {
  auto axis = [&](const std::string& field) -> const Axis* {
    for (const auto& a : s.axes)
      if (a.field == field) return &a;
    return nullptr;
  };
  const Axis* area = axis(area_axis);
  if (!s.levels()) {
    if (area)
      throw io::BadInput(s.file + ": key '" + area->key +
                         ".field': 'area_constant' makes a level (C1, C0) of an energy-momentum "
                         "map and needs \"level_orbits\": M (1 to " +
                         std::to_string(kMaxLevelOrbits) + ")");
    return;
  }
  if (!area || !axis(energy_axis))
    r.fail("level_orbits",
           "an energy-momentum map needs an 'energy' axis (C1) and an 'area_constant' axis (C0)");
  if (!s.ftle)
    r.fail("level_orbits", "an energy-momentum map needs \"ftle\" (true or {\"window\": ...})");
  if (s.reference)
    r.fail("reference", "not with \"level_orbits\" (an energy-momentum map measures the FTLE)");
  for (const auto& a : s.axes)
    if (a.field.starts_with("omega") || a.field.starts_with("gamma"))
      throw io::BadInput(s.file + ": key '" + a.key + ".field': '" + a.field +
                         "' cannot vary with \"level_orbits\": the level gives the initial states");
}

}  // namespace

long SweepSpec::point_count() const {
  long n = 1;
  for (const auto& a : axes) n *= long(a.values.size());
  return n;
}

std::vector<std::size_t> SweepSpec::coordinates(long index) const {
  std::vector<std::size_t> c(axes.size());
  for (std::size_t k = axes.size(); k-- > 0;) {
    const long n = long(axes[k].values.size());
    c[k] = std::size_t(index % n);
    index /= n;
  }
  return c;
}

std::vector<long> SweepSpec::value_probes() const {
  std::vector<long> probes;
  long stride = 1;  // the last axis varies fastest (coordinates)
  for (std::size_t k = axes.size(); k-- > 0;) {
    for (long j = 0; j < long(axes[k].values.size()); ++j) probes.push_back(j * stride);
    stride *= long(axes[k].values.size());
  }
  std::sort(probes.begin(), probes.end());
  probes.erase(std::unique(probes.begin(), probes.end()), probes.end());
  return probes;
}

SweepSpec read_sweep(const Json& root, const std::string& file) {
  io::ObjectReader r(root, file);
  SweepSpec s;
  s.file = file;
  if (auto sim = r.object("simulation")) {
    s.base = job::read_simulation_fields(*sim);
    sim->finish();
  }
  const Json* axes = r.raw("axes");
  if (!axes) r.fail("axes", "missing: a list of {\"field\": ..., \"values\": [...]} objects");
  if (!axes->is_array() || axes->empty() || axes->size() > 16)
    r.fail("axes", "expected a list of 1 to 16 axes, got " + io::describe(*axes));
  long points = 1;
  for (std::size_t k = 0; k < axes->size(); ++k) {
    s.axes.push_back(read_axis((*axes)[k], file, k));
    for (std::size_t j = 0; j < k; ++j)
      if (s.axes[j].field == s.axes[k].field)
        throw io::BadInput(file + ": key 'axes[" + std::to_string(k) + "].field': '" +
                           s.axes[k].field + "' is already axes[" + std::to_string(j) + "]");
    points *= long(s.axes[k].values.size());
    if (points > max_points)
      throw io::BadInput(file + ": key 'axes': more than " + std::to_string(max_points) +
                         " points; split the sweep into several files");
  }
  if (auto ref = r.boolean("reference")) s.reference = *ref;
  if (auto m = r.integer("level_orbits", 1, kMaxLevelOrbits)) s.level_orbits = int(*m);
  if (r.has("ftle")) {
    const Json* f = r.raw("ftle");
    if (f->is_boolean()) {
      if (f->get<bool>()) s.ftle = FtleSettings{};
    } else if (f->is_object()) {
      io::ObjectReader fr(*f, file, "ftle");
      FtleSettings st;
      if (auto v = fr.number_in("separation", 1e-14, 1e-2, "1e-14 to 0.01")) st.separation = *v;
      if (auto v = fr.positive_number("window")) st.window = *v;
      if (auto v = fr.boolean("curve")) st.curve = *v;
      fr.finish();
      s.ftle = st;
    } else {
      r.fail("ftle",
             "expected true, false or {\"separation\": ..., \"window\": ..., \"curve\": ...}, "
             "got " +
                 io::describe(*f));
    }
  }
  check_levels(r, s);
  if (s.ftle && s.ftle->curve) {
    if (s.levels())
      r.fail("ftle", "\"curve\" follows single orbits, not an energy-momentum map's levels");
    if (points > kMaxCurvePoints)
      r.fail("ftle", "\"curve\": at most " + std::to_string(kMaxCurvePoints) +
                         " points (merge draws every curve in one chart), this sweep has " +
                         std::to_string(points));
  }
  if (r.has("atlas")) {
    const Json* a = r.raw("atlas");
    if (!a->is_array()) r.fail("atlas", "expected a list of {\"metric\", \"x\", \"y\"} objects");
    for (std::size_t i = 0; i < a->size(); ++i) {
      const std::string key = "atlas[" + std::to_string(i) + "]";
      if (!(*a)[i].is_object()) r.fail(key, "expected an object {\"metric\", \"x\", \"y\"}");
      io::ObjectReader ar((*a)[i], file, key);
      AtlasRequest q;
      auto m = ar.string("metric");
      auto x = ar.string("x");
      auto y = ar.string("y");
      if (!m) ar.fail("metric", "missing");
      if (!x) ar.fail("x", "missing");
      if (!y) ar.fail("y", "missing");
      q.metric = *m;
      q.x = *x;
      q.y = *y;
      if (auto v = ar.number("min")) q.min = *v;
      if (auto v = ar.number("max")) q.max = *v;
      if (!(std::isnan(q.min) || std::isnan(q.max) || q.min < q.max))
        ar.fail("max", "must be larger than \"min\"");
      for (const auto* name : {&q.x, &q.y}) {
        bool found = false;
        for (const auto& ax : s.axes) found |= ax.field == *name;
        if (!found)
          ar.fail(name == &q.x ? "x" : "y",
                  "'" + io::printable(*name) + "' is not one of the sweep's axes");
      }
      std::vector<std::string> axis_names;
      for (const auto& ax : s.axes) axis_names.push_back(ax.field);
      if (!metric_in_rows(q.metric, s.reference, s.ftle.has_value(), axis_names, s.levels())) {
        std::string allowed;
        for (const auto& k : level_row_metrics()) allowed += (allowed.empty() ? "" : ", ") + k;
        if (!s.levels())
          allowed = atlas_metrics_allowed(s.reference, s.ftle.has_value(), axis_names);
        ar.fail("metric", "'" + io::printable(q.metric) +
                              "' is not in this sweep's rows (allowed: " + allowed + ")");
      }
      ar.finish();
      s.atlases.push_back(q);
    }
  }
  if (auto c = r.object("self_check")) {
    if (auto v = c->number_in("threshold", 1e-6, 1.0, "1e-6 to 1 (a share of the colour bar)"))
      s.self_check_threshold = *v;
    c->finish();
  }
  r.finish();
  s.hash = shard::checksum_of(io::json_text(root));  // nlohmann::json keeps keys sorted
  return s;
}

SweepSpec read_sweep_file(const std::filesystem::path& path) {
  return read_sweep(io::read_json_file(path), path.string());
}

}  // namespace epviz::sweep
