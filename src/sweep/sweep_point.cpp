#include "sweep/sweep_point.hpp"

#include <cmath>
#include <stdexcept>

#include "io/json_reader.hpp"
#include "job/schema.hpp"
#include "physics/cases.hpp"
#include "physics/invariants.hpp"

namespace epviz::sweep {
namespace {

using Json = nlohmann::json;

// The vector field `name` as the point has it so far: given, or the preset's.
std::array<double, 3> current_vector(const job::SimulationFields& f, const std::string& name) {
  const job::Given<std::array<double, 3>>* given = name == "inertia" ? &f.inertia
                                                   : name == "com"   ? &f.com
                                                   : name == "omega" ? &f.omega
                                                                     : &f.gamma;
  if (*given) return **given;
  auto c = f.case_name ? physics::case_from_name(*f.case_name) : std::nullopt;
  if (!c || *c == physics::Case::custom) c = physics::Case::generic;
  const auto& p = physics::preset(*c);
  const Eigen::Vector3d v = name == "inertia" ? p.body.inertia
                            : name == "com"   ? p.body.com
                            : name == "omega" ? p.initial.omega
                                              : p.initial.gamma;
  return {v[0], v[1], v[2]};
}

std::optional<bool> method_is_adaptive(const job::SimulationFields& f) {
  const auto m =
      sim::method_from_name(f.method ? *f.method : std::string(sim::name(sim::RunSpec{}.method)));
  if (!m) return std::nullopt;
  return sim::is_adaptive(*m);
}

}  // namespace

PointFields point_fields(const SweepSpec& spec, long index) {
  PointFields p;
  p.index = index;
  p.fields = spec.base;
  const auto at = spec.coordinates(index);
  // Plain fields first, then components (which start from the vector the
  // plain fields and the case give), so that the order of the axes does not matter.
  for (int pass = 0; pass < 2; ++pass) {
    for (std::size_t k = 0; k < spec.axes.size(); ++k) {
      const auto& axis = spec.axes[k];
      const Json& value = axis.values[at[k]];
      const auto bracket = axis.field.find('[');
      if ((bracket != std::string::npos) != (pass == 1)) continue;
      p.axis_values[axis.field] = value;
      const std::string origin =
          spec.file + ": key '" + axis.key + "' (" + axis.field + " = " + value.dump() + ")";
      if (axis.field == "energy") {
        p.energy = value.get<double>();
        p.energy_origin = origin;
        continue;
      }
      Json one = Json::object();
      std::string name = axis.field;
      if (bracket != std::string::npos) {
        name = axis.field.substr(0, bracket);
        auto v = current_vector(p.fields, name);
        v[std::size_t(axis.field[bracket + 1] - '0')] = value.get<double>();
        one[name] = v;
      } else {
        one[name] = value;
      }
      io::ObjectReader r(one, spec.file, axis.key);
      job::SimulationFields given = job::read_simulation_fields(r);
      r.finish();
      p.fields.overlay(given);
      // Messages about the value (resolve's) name the axis and the value.
      if (name == "inertia") p.fields.inertia.origin = origin;
      if (name == "com") p.fields.com.origin = origin;
      if (name == "omega") p.fields.omega.origin = origin;
      if (name == "gamma") p.fields.gamma.origin = origin;
      if (name == "weight") p.fields.weight.origin = origin;
      if (name == "case") p.fields.case_name.origin = origin;
      if (name == "method") p.fields.method.origin = origin;
      if (name == "formulation") p.fields.formulation.origin = origin;
      if (name == "step") p.fields.step.origin = origin;
      if (name == "tol") p.fields.tol.origin = origin;
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
  return p;
}

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
  spec.initial.omega = w * std::sqrt((energy - potential) / kinetic);
}

}  // namespace epviz::sweep
