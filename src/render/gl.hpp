#pragma once
// The one place that includes the OpenGL headers. libOSMesa exports every GL
// entry point, so with GL_GLEXT_PROTOTYPES (set by CMake) the core-profile
// functions are plain declarations and no loader is needed.
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>

#include <string_view>

namespace epviz::render {

// Throws std::runtime_error naming `where` and the GL error if one is pending.
void check_gl_error(std::string_view where);

}  // namespace epviz::render
