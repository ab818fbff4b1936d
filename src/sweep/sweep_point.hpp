#pragma once
// One point of a sweep: the base simulation fields with the point's axis
// values put in, each read by the job format's own reader (so a value is
// checked exactly as the same key in a render job would be), and the energy
// level to reach, if an axis gives one.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "job/document.hpp"
#include "sim/run_spec.hpp"
#include "sweep/sweep_spec.hpp"

namespace epviz::sweep {

struct PointFields {
  long index = 0;
  job::SimulationFields fields;
  // Total energy C1: the initial omega is scaled to it, or, with `area`, the
  // level (C1, C0) an energy-momentum map's orbits start on.
  std::optional<double> energy;
  std::string energy_origin;
  std::optional<double> area;  // the area constant C0 of the level
  // The point's value of each axis, by field name, in axis order.
  nlohmann::ordered_json axis_values = nlohmann::ordered_json::object();
  // Axes that do not apply to this point: "step" for an adaptive method,
  // "tol" for a fixed-step one (a sweep over methods and steps crosses both).
  std::vector<std::string> ignored;
};

// Reads a sweep's points in turn. Each axis value is read by the job
// format's reader once, when a point first takes it, not once per point: a
// sweep of a million points over a few hundred values reads a few hundred
// (the reader, not the run, was a short run's largest cost outside the
// integration). operator() throws io::BadInput naming the sweep file and the
// axis for a value the field does not accept.
class PointReader {
 public:
  explicit PointReader(const SweepSpec& spec);  // `spec` must outlive the reader
  PointFields operator()(long index);

 private:
  // Where an axis's values go, from its field name, worked out once.
  struct AxisTarget {
    enum class Kind { field, component, energy, area } kind = Kind::field;
    std::string vector;         // a component's vector: "inertia", "com", "omega" or "gamma"
    std::size_t component = 0;  // and its index, 0 to 2
  };
  struct ReadValue {
    std::string origin;              // "FILE: key 'axes[1]' (step = 0.01)"; empty: not read yet
    job::SimulationFields fields;    // what a plain field's value gives
    bool checked_in_vector = false;  // a component's range, checked in its vector
  };
  ReadValue& value(std::size_t axis_index, std::size_t value_index);
  // An FTLE window is held to as many windows per run as a fixed step is
  // to steps (job::max_steps_per_run), over the point's t_end.
  void check_ftle_windows(const PointFields& p) const;

  const SweepSpec& spec_;
  std::vector<AxisTarget> targets_;             // [axis]
  std::vector<std::vector<ReadValue>> values_;  // [axis][value]
};

// One point, read alone (a PointReader for many).
PointFields point_fields(const SweepSpec& spec, long index);

// Scales spec.initial.omega so that the total energy C1 is `energy`, keeping
// its direction and gamma. Throws std::invalid_argument (the message starts
// with `origin`) when no such scaling exists: omega is zero, or `energy` is
// below the potential energy of the initial gamma, or the omega reached is
// past omega's range (job/fields.hpp).
void set_energy(sim::RunSpec& spec, double energy, const std::string& origin);

// The resolved run of a point: fields checked and defaults filled (the
// caller's resolver, which is `epviz simulate`'s), then the energy level set
// (unless the point is a level (C1, C0), whose states come from the level).
template <class Resolver>
sim::RunSpec resolve_point(const PointFields& p, const Resolver& resolve) {
  sim::RunSpec run = resolve(p.fields);
  if (p.energy && !p.area) set_energy(run, *p.energy, p.energy_origin);
  return run;
}

}  // namespace epviz::sweep
