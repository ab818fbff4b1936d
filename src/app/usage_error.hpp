#pragma once
// Bad input from the command line: io::BadInput, the one type every reader's
// error derives from (the CLI prints its one-line message and exits 2).
#include "io/bad_input.hpp"

namespace epviz::app {

using UsageError = io::BadInput;

}  // namespace epviz::app
