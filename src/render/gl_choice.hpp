#pragma once
// The GL backend a command draws with, chosen once from its --gl option or
// the environment, and the one way a command opens its context. A name that
// is not a backend is bad input (io::BadInput, exit code 2), refused when the
// choice is made, before any work; a backend that cannot run here is
// GlUnavailable when the context is opened (exit code 1: the input was fine,
// the machine lacks a library).
#include <memory>
#include <string>

#include "render/gl_context.hpp"

namespace epviz::render {

class GlChoice {
 public:
  // `option`: the value of --gl, "" when not given (then EPVIZ_GL, else "auto").
  // Throws io::BadInput naming --gl or EPVIZ_GL and the allowed names.
  explicit GlChoice(const std::string& option);

  const std::string& backend() const { return backend_; }

  // A current context for drawing into framebuffers of one's own: its own
  // surface is never read, so it stays tiny. Throws GlUnavailable.
  std::unique_ptr<GlContext> open() const;

 private:
  std::string backend_;
};

}  // namespace epviz::render
