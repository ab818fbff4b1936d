#include "sweep/sweep_point.hpp"

#include <cmath>
#include <stdexcept>

#include "io/json_reader.hpp"
#include "io/json_text.hpp"
#include "io/printable.hpp"
#include "job/fields.hpp"
#include "job/schema.hpp"
#include "physics/cases.hpp"
#include "physics/invariants.hpp"

namespace epviz::sweep {
namespace {

using Json = nlohmann::json;

// The vector field called `name` ("inertia", "com", "omega" or "gamma").
job::Given<std::array<double, 3>>& vector_field(job::SimulationFields& f, const std::string& name) {
  return name == "inertia" ? f.inertia
         : name == "com"   ? f.com
         : name == "omega" ? f.omega
                           : f.gamma;
}

// The vector field `name` as the point has it so far: given, or the preset's.
std::array<double, 3> current_vector(job::SimulationFields& f, const std::string& name) {
  if (const auto& given = vector_field(f, name)) return *given;
  auto c = f.case_name ? physics::case_from_name(*f.case_name) : std::nullopt;
  if (!c || *c == physics::Case::custom) c = physics::Case::generic;
  const auto& p = physics::preset(*c);
  const Eigen::Vector3d v = name == "inertia" ? p.body.inertia
                            : name == "com"   ? p.body.com
                            : name == "omega" ? p.initial.omega
                                              : p.initial.gamma;
  return {v[0], v[1], v[2]};
}

// Every field `f` gives was given by `origin`, so messages about it name the axis.
void set_origin(job::SimulationFields& f, const std::string& origin) {
  job::for_each_field(f, [&](const job::FieldInfo&, auto& given) {
    if (given) given.origin = origin;
  });
}

// {name: value} read by the job format's reader: the fields it gives.
job::SimulationFields read_one(const SweepSpec& spec, const Axis& axis, const std::string& name,
                               const Json& value) {
  Json one = Json::object();
  one[name] = value;
  io::ObjectReader r(one, spec.file, axis.key);
  job::SimulationFields given = job::read_simulation_fields(r);
  r.finish();
  return given;
}

std::optional<bool> method_is_adaptive(const job::SimulationFields& f) {
  const auto m =
      sim::method_from_name(f.method ? *f.method : std::string(sim::name(sim::RunSpec{}.method)));
  if (!m) return std::nullopt;
  return sim::is_adaptive(*m);
}

}  // namespace

PointReader::PointReader(const SweepSpec& spec) : spec_(spec) {
  for (const Axis& axis : spec.axes) {
    AxisTarget t;
    if (axis.field == energy_axis) {
      t.kind = AxisTarget::Kind::energy;
    } else if (axis.field == area_axis) {
      t.kind = AxisTarget::Kind::area;
    } else if (const auto bracket = axis.field.find('['); bracket != std::string::npos) {
      // "omega[1]": the axis reader accepts only this form.
      t.kind = AxisTarget::Kind::component;
      t.vector = axis.field.substr(0, bracket);
      t.component = std::size_t(axis.field[bracket + 1] - '0');
    }
    targets_.push_back(t);
    values_.emplace_back(axis.values.size());
  }
}

PointReader::ReadValue& PointReader::value(std::size_t axis_index, std::size_t value_index) {
  ReadValue& v = values_[axis_index][value_index];
  if (!v.origin.empty()) return v;
  const Axis& axis = spec_.axes[axis_index];
  const Json& value = axis.values[value_index];
  // Quoted short and on one line: a value may be a 100 KB string.
  std::string origin = spec_.file + ": key '" + axis.key + "' (" + axis.field + " = " +
                       io::printable(io::json_text(value), 60) + ")";
  // A component is checked in the vector it goes into, by operator() at the
  // first point that takes it.
  if (targets_[axis_index].kind == AxisTarget::Kind::field) {
    v.fields = read_one(spec_, axis, axis.field, value);
    set_origin(v.fields, origin);
  }
  v.origin = std::move(origin);
  return v;
}

PointFields PointReader::operator()(long index) {
  PointFields p;
  p.index = index;
  p.fields = spec_.base;
  const auto at = spec_.coordinates(index);
  // Plain fields first, then components (which start from the vector the
  // plain fields and the case give), so that the order of the axes does not matter.
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t k = 0; k < spec_.axes.size(); ++k) {
      const AxisTarget& target = targets_[k];
      if ((target.kind == AxisTarget::Kind::component) != (pass == 1)) continue;
      const Axis& axis = spec_.axes[k];
      const Json& value = axis.values[at[k]];
      p.axis_values[axis.field] = value;
      ReadValue& read = this->value(k, at[k]);
      switch (target.kind) {
        case AxisTarget::Kind::energy:
          p.energy = value.get<double>();
          p.energy_origin = read.origin;
          break;
        case AxisTarget::Kind::area: p.area = value.get<double>(); break;
        case AxisTarget::Kind::field: p.fields.overlay(read.fields); break;
        case AxisTarget::Kind::component: {
          auto v = current_vector(p.fields, target.vector);
          v[target.component] = value.get<double>();
          if (!read.checked_in_vector) {
            // The vector's range holds per component, and the other components
            // are valid (given, or the preset's): one check per value does.
            read_one(spec_, axis, target.vector, Json(v));
            read.checked_in_vector = true;
          }
          vector_field(p.fields, target.vector).set(v, read.origin);
          break;
        }
      }
    }
  }
  // A step means nothing to an adaptive method, a tolerance nothing to a
  // fixed-step one: across a method axis the one that does not apply is
  // left out of that point (and named in its row), not an error.
  const auto adaptive = method_is_adaptive(p.fields);
  auto axis_given = [&](const char* f) { return p.axis_values.contains(f); };
  if (adaptive && *adaptive && axis_given("step")) {
    p.fields.step = {};
    p.ignored.emplace_back("step");
  }
  if (adaptive && !*adaptive && axis_given("tol")) {
    p.fields.tol = {};
    p.ignored.emplace_back("tol");
  }
  check_ftle_windows(p);
  return p;
}

void PointReader::check_ftle_windows(const PointFields& p) const {
  if (!spec_.ftle || !(spec_.ftle->window > 0.0)) return;
  const double t_end = p.fields.t_end ? *p.fields.t_end : sim::RunSpec{}.t_end;
  const double least = t_end / job::max_steps_per_run;
  if (!(spec_.ftle->window >= least))
    throw io::BadInput(spec_.file + ": key 'ftle.window': expected a window from t_end / " +
                       job::format_number(job::max_steps_per_run) + " (" +
                       job::format_number(least) + " at point " + std::to_string(p.index) +
                       ", t_end " + job::format_number(t_end) + "), got " +
                       job::format_number(spec_.ftle->window));
}

PointFields point_fields(const SweepSpec& spec, long index) { return PointReader(spec)(index); }

void set_energy(sim::RunSpec& spec, double energy, const std::string& origin) {
  const auto inv =
      physics::invariants(spec.body, physics::Case::custom, spec.initial.omega, spec.initial.gamma);
  const Eigen::Vector3d& w = spec.initial.omega;
  const double kinetic = 0.5 * (spec.body.inertia.array() * w.array() * w.array()).sum();
  const double potential = inv.energy - kinetic;
  if (!(kinetic > 0.0))
    throw std::invalid_argument(origin +
                                ": an energy level scales the initial omega, which is zero here; "
                                "give a nonzero omega in \"simulation\"");
  if (!(energy >= potential))
    throw std::invalid_argument(origin + ": below the potential energy " +
                                std::to_string(potential) +
                                " of the initial gamma, the lowest energy with this gamma");
  const Eigen::Vector3d scaled = w * std::sqrt((energy - potential) / kinetic);
  // The omega it reaches is held to omega's own range, as a given omega is.
  const auto& field = *job::find_field("omega");
  for (double x : scaled)
    if (!field.in_range(x))
      throw std::invalid_argument(origin + ": gives an omega past omega's range (expected " +
                                  field.range_text() + "); choose a lower energy");
  spec.initial.omega = scaled;
}

}  // namespace epviz::sweep
