#pragma once
// A shared library opened with dlopen when a backend is first used. Handles
// are never closed: GL drivers do not survive being unloaded and reloaded.
#include <string>

namespace epviz::render {

class SharedLibrary {
 public:
  // Opens `soname` (e.g. "libEGL.so.1"); throws GlUnavailable (gl_context.hpp)
  // naming the library and the Debian packages that provide it.
  SharedLibrary(const std::string& soname, const std::string& debian_packages);

  // The address of `name`, or nullptr.
  void* symbol(const char* name) const;
  // The address of `name`; throws GlUnavailable when the library lacks it.
  void* required_symbol(const char* name) const;

  template <typename Function>
  Function required(const char* name) const {
    return reinterpret_cast<Function>(required_symbol(name));
  }

 private:
  void* handle_ = nullptr;
  std::string soname_;
};

}  // namespace epviz::render
