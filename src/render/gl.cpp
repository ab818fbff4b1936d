#include "render/gl.hpp"

#include <stdexcept>
#include <string>

namespace epviz::render {
namespace {

const char* gl_error_name(GLenum error) {
  switch (error) {
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION: return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "unknown GL error";
  }
}

}  // namespace

void check_gl_error(std::string_view where) {
  const GLenum error = glGetError();
  if (error == GL_NO_ERROR) return;
  // Drain the queue so the next check reports only new errors.
  while (glGetError() != GL_NO_ERROR) {
  }
  throw std::runtime_error("OpenGL error " + std::string(gl_error_name(error)) + " in " +
                           std::string(where));
}

}  // namespace epviz::render
