#pragma once
// What the user of the interactive view can do about a numerical failure,
// worded with the panel's own controls (numerics/ only reports the kind of
// trouble and the fact).
#include <string>

#include "numerics/failure.hpp"

namespace epviz::live {

// One complete sentence, lower-case first word, ending in a full stop, naming
// the control to change. `adaptive`: the method chose its steps by a tolerance.
std::string failure_advice(numerics::FailureKind kind, bool adaptive);

// The text after "Stopped: " in the panel: "<method> failed at t = <t>: <detail>; <advice>".
std::string failure_line(const numerics::Failure& f, bool adaptive);

}  // namespace epviz::live
