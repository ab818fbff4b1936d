#pragma once
// What a command-line user can do about a numerical failure. numerics/ reports
// the kind of trouble and the fact; the advice names the settings the user
// actually has: options of `epviz simulate`, or the keys of a render job.
#include <string>
#include <string_view>

#include "numerics/failure.hpp"

namespace epviz::app {

// Where the user changes the run's settings.
enum class SettingsIn {
  command_line,  // epviz simulate: --tol, --step, --method, ...
  render_job,    // epviz render: the job file's simulation.tol, simulation.step, ...
};

// One complete sentence, lower-case first word, ending in a full stop, naming
// the setting to change. `adaptive`: the method chose its steps by a tolerance.
std::string failure_advice(numerics::FailureKind kind, std::string_view method, bool adaptive,
                           SettingsIn where = SettingsIn::command_line);

// The line users see: "<method> failed at t = <t>: <detail>; <advice>". Whether
// the method is adaptive is read from the method table by its name.
std::string failure_line(const numerics::Failure& f, SettingsIn where = SettingsIn::command_line);

}  // namespace epviz::app
