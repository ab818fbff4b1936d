#pragma once
// The one place that includes the OpenGL declarations. The executable links no
// GL library: every gl function is a pointer the backend fills at run time
// (gl_loader.hpp), so simulate and the other commands that draw nothing never
// load Mesa or LLVM.
#include "render/gl_loader.hpp"

#include <string_view>

namespace epviz::render {

// Throws std::runtime_error naming `where` and the GL error if one is pending.
void check_gl_error(std::string_view where);

}  // namespace epviz::render
