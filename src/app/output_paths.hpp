#pragma once
// The old place of io/output_paths.hpp, kept only for merge_command.cpp until
// it includes that header itself.
#include "io/output_paths.hpp"

namespace epviz::app {

using io::check_output_dir;

}  // namespace epviz::app
