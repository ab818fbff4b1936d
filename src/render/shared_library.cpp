#include "render/shared_library.hpp"

#include <dlfcn.h>

#include "render/gl_context.hpp"

namespace epviz::render {

SharedLibrary::SharedLibrary(const std::string& soname, const std::string& debian_packages)
    : soname_(soname) {
  handle_ = dlopen(soname.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle_ == nullptr) {
    const char* why = dlerror();
    throw GlUnavailable(soname + " cannot be loaded (" + (why != nullptr ? why : "not found") +
                        "); install the Debian package" +
                        (debian_packages.find(' ') != std::string::npos ? "s " : " ") +
                        debian_packages);
  }
}

void* SharedLibrary::symbol(const char* name) const { return dlsym(handle_, name); }

void* SharedLibrary::required_symbol(const char* name) const {
  void* address = symbol(name);
  if (address == nullptr) throw GlUnavailable(soname_ + " has no " + std::string(name));
  return address;
}

}  // namespace epviz::render
