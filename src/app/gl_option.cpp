#include "app/gl_option.hpp"

namespace epviz::app {

void add_gl_option(cli::Command command, std::string& value, const std::string& what_for) {
  command.add_option("--gl", value,
                     "offscreen GL backend" + (what_for.empty() ? "" : " " + what_for) +
                         ": auto, egl or osmesa (default: $EPVIZ_GL or auto)");
}

}  // namespace epviz::app
