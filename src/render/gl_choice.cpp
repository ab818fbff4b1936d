#include "render/gl_choice.hpp"

#include <algorithm>

#include "io/bad_input.hpp"
#include "io/printable.hpp"

namespace epviz::render {

GlChoice::GlChoice(const std::string& option)
    : backend_(option.empty() ? gl_backend_from_environment() : option) {
  const auto names = gl_backends();
  if (std::find(names.begin(), names.end(), backend_) != names.end()) return;
  std::string allowed;
  for (const auto& name : names) allowed += (allowed.empty() ? "" : ", ") + name;
  throw io::BadInput(std::string(option.empty() ? "EPVIZ_GL" : "--gl") + ": unknown GL backend '" +
                     io::printable(backend_) + "' (allowed: " + allowed + ")");
}

std::unique_ptr<GlContext> GlChoice::open() const { return make_gl_context(backend_, 16, 16); }

}  // namespace epviz::render
