#pragma once
// The --gl option of every command that draws, defined once: the value stays
// "" when the option is not given, which render::GlChoice reads as "EPVIZ_GL,
// else auto".
#include <string>

#include "app/cli.hpp"

namespace epviz::app {

// `what_for` ends the help's first words: "offscreen GL backend for the charts".
void add_gl_option(cli::Command command, std::string& value, const std::string& what_for = "");

}  // namespace epviz::app
