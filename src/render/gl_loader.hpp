#pragma once
// OpenGL entry points as function pointers filled at run time, so that the
// executable links no GL library: the backend (EGL or OSMesa, both dlopen'ed
// only when something is drawn) hands its GetProcAddress to load_gl_functions().
// <GL/glcorearb.h> gives the core-profile types and PFNGL...PROC pointer types;
// gl_functions.hpp lists the functions the renderer calls and maps each gl name
// to its pointer (epviz_glClear for glClear).
#include <GL/glcorearb.h>

#include <string>
#include <string_view>

#include "render/gl_functions.hpp"

#define EPVIZ_GL_DECLARE_POINTER(type, name) extern type epviz_##name;
EPVIZ_GL_FUNCTIONS(EPVIZ_GL_DECLARE_POINTER)
#undef EPVIZ_GL_DECLARE_POINTER

namespace epviz::render {

// Resolves one GL function by name; nullptr when the implementation lacks it.
using GlProcLookup = void* (*)(const char* name);

// Fills every pointer from `lookup` when `source` (the backend's name) differs
// from the one that filled them last; a no-op otherwise. Throws
// std::runtime_error naming the functions the implementation does not have.
// Not thread-safe: contexts of different backends must not be current on two
// threads at once (epviz uses one backend per process).
void load_gl_functions(std::string_view source, GlProcLookup lookup);

// The source that filled the table last ("" before the first load).
std::string loaded_gl_functions_source();

}  // namespace epviz::render
