#pragma once
// What a user can do about a numerical failure, worded with the settings of
// the front end in use: the options of `epviz simulate`, the keys of a render
// job, the controls of the interactive panel, or the keywords of the Python
// module's epviz.simulate. numerics/ reports the kind of
// trouble and the fact; the remedy for each kind is chosen here, once for all
// three, and only the names of the settings differ.
#include <string>
#include <string_view>

#include "numerics/failure.hpp"

namespace epviz::sim {

// Where the user changes the run's settings.
enum class SettingsIn {
  command_line,  // epviz simulate: --tol, --step, --method, ...
  render_job,    // epviz render: the job file's simulation.tol, simulation.step, ...
  panel,         // epviz serve: the Integrator panel and the Case and body panel
  python,        // the Python module: epviz.simulate(tol=..., step=..., ...)
};

// One complete sentence, lower-case first word, ending in a full stop, naming
// the setting to change. `adaptive`: the method chose its steps by a tolerance.
std::string failure_advice(numerics::FailureKind kind, std::string_view method, bool adaptive,
                           SettingsIn where);

// The line users see: "<method> failed at t = <t>: <detail>; <advice>". Whether
// the method is adaptive is read from the method table by its name.
std::string failure_line(const numerics::Failure& f, SettingsIn where);

}  // namespace epviz::sim
