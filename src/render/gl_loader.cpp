#define EPVIZ_GL_LOADER_DEFINITIONS 1
#include "render/gl_loader.hpp"

#include <stdexcept>

#define EPVIZ_GL_DEFINE_POINTER(type, name) type epviz_##name = nullptr;
EPVIZ_GL_FUNCTIONS(EPVIZ_GL_DEFINE_POINTER)
#undef EPVIZ_GL_DEFINE_POINTER

namespace epviz::render {
namespace {

std::string& current_source() {
  static std::string source;
  return source;
}

}  // namespace

void load_gl_functions(std::string_view source, GlProcLookup lookup) {
  if (current_source() == source) return;
  std::string missing;
#define EPVIZ_GL_LOAD_POINTER(type, name)               \
  epviz_##name = reinterpret_cast<type>(lookup(#name)); \
  if (epviz_##name == nullptr) missing += (missing.empty() ? "" : ", ") + std::string(#name);
  EPVIZ_GL_FUNCTIONS(EPVIZ_GL_LOAD_POINTER)
#undef EPVIZ_GL_LOAD_POINTER
  if (!missing.empty()) {
    current_source().clear();
    throw std::runtime_error("the " + std::string(source) + " OpenGL implementation lacks " +
                             missing);
  }
  current_source() = source;
}

std::string loaded_gl_functions_source() { return current_source(); }

}  // namespace epviz::render
