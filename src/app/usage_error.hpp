#pragma once
// The old name of io::BadInput, kept only for bench_command.cpp and
// merge_command.cpp until they name io::BadInput themselves.
#include "io/bad_input.hpp"

namespace epviz::app {

using UsageError = io::BadInput;

}  // namespace epviz::app
