#pragma once
// The fields that describe a simulation, as given on the command line or in a
// job file, before they are checked against each other and against physics.
// Each field remembers where it came from ("--inertia", "job.json: key 'inertia'")
// so that an error names what the user wrote.
#include <array>
#include <optional>
#include <string>

#include "io/json_reader.hpp"
#include "sim/run_spec.hpp"

namespace epviz::app {

template <class T>
struct Given {
  std::optional<T> value;
  std::string origin;  // where the value came from, for messages
  explicit operator bool() const { return value.has_value(); }
  const T& operator*() const { return *value; }
  void set(T v, std::string from) { value = std::move(v); origin = std::move(from); }
};

struct SimulationFields {
  Given<std::string> case_name;
  Given<std::array<double, 3>> inertia, com, omega, gamma;
  Given<double> weight, tol, step, t_end;
  Given<long> samples;
  Given<std::string> formulation, method;
  Given<bool> allow_nonphysical, normalize_gamma, chart_switch;

  // Fields given in `over` replace those here (the command line over a job file).
  void overlay(const SimulationFields& over);
};

// Reads the simulation keys of a job object (the same names as the CLI options,
// with '_' for '-'); unknown keys are left for the caller's finish(). With
// `auto_tol` (render jobs), "tol": "auto" is accepted and reported there.
SimulationFields read_simulation_fields(io::ObjectReader& reader, bool* auto_tol = nullptr);

// Checks the fields against each other and against physics and fills in the
// defaults: a case preset's body and state for fields not given (the generic
// body, labelled custom, without a case). Throws UsageError naming the origin.
sim::RunSpec resolve(const SimulationFields& fields);

}  // namespace epviz::app
