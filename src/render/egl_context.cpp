#include "render/egl_context.hpp"

// Only types and constants from the EGL headers: every call goes through a
// pointer from dlsym/eglGetProcAddress, so nothing links libEGL.
#define EGL_NO_X11 1
#define EGL_EGL_PROTOTYPES 0
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "render/gl.hpp"
#include "render/shared_library.hpp"

namespace epviz::render {
namespace {

struct EglApi {
  SharedLibrary library{"libEGL.so.1", "libegl1 and libegl-mesa0"};
  PFNEGLGETPROCADDRESSPROC get_proc_address =
      library.required<PFNEGLGETPROCADDRESSPROC>("eglGetProcAddress");
  PFNEGLQUERYSTRINGPROC query_string = library.required<PFNEGLQUERYSTRINGPROC>("eglQueryString");
  PFNEGLINITIALIZEPROC initialize = library.required<PFNEGLINITIALIZEPROC>("eglInitialize");
  PFNEGLCHOOSECONFIGPROC choose_config =
      library.required<PFNEGLCHOOSECONFIGPROC>("eglChooseConfig");
  PFNEGLBINDAPIPROC bind_api = library.required<PFNEGLBINDAPIPROC>("eglBindAPI");
  PFNEGLCREATECONTEXTPROC create_context =
      library.required<PFNEGLCREATECONTEXTPROC>("eglCreateContext");
  PFNEGLDESTROYCONTEXTPROC destroy_context =
      library.required<PFNEGLDESTROYCONTEXTPROC>("eglDestroyContext");
  PFNEGLMAKECURRENTPROC make_current = library.required<PFNEGLMAKECURRENTPROC>("eglMakeCurrent");
  PFNEGLGETCURRENTCONTEXTPROC get_current_context =
      library.required<PFNEGLGETCURRENTCONTEXTPROC>("eglGetCurrentContext");
  PFNEGLGETERRORPROC get_error = library.required<PFNEGLGETERRORPROC>("eglGetError");
  // Extensions (nullptr when the implementation lacks them).
  PFNEGLGETPLATFORMDISPLAYEXTPROC get_platform_display =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
          get_proc_address("eglGetPlatformDisplayEXT"));
  PFNEGLQUERYDEVICESEXTPROC query_devices =
      reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(get_proc_address("eglQueryDevicesEXT"));
  PFNEGLQUERYDEVICESTRINGEXTPROC query_device_string =
      reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(get_proc_address("eglQueryDeviceStringEXT"));
};

const EglApi& egl() {
  static const EglApi api;
  return api;
}

void* egl_proc(const char* name) { return reinterpret_cast<void*>(egl().get_proc_address(name)); }

bool has_extension(const char* list, const std::string& name) {
  if (list == nullptr) return false;
  const std::string all = std::string(" ") + list + " ";
  return all.find(" " + name + " ") != std::string::npos;
}

std::string egl_error() {
  char text[16];
  std::snprintf(text, sizeof text, "0x%04X", static_cast<unsigned>(egl().get_error()));
  return text;
}

struct Candidate {
  std::string platform;
  EGLDisplay display;
};

// Hardware devices first: Mesa lists its software rasteriser as a device too
// (EGL_MESA_device_software), which the surfaceless platform reaches anyway.
std::vector<Candidate> candidate_displays() {
  const auto& api = egl();
  std::vector<Candidate> candidates;
  if (api.get_platform_display == nullptr) return candidates;
  const char* client = api.query_string(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (api.query_devices != nullptr && api.query_device_string != nullptr &&
      has_extension(client, "EGL_EXT_platform_device")) {
    EGLDeviceEXT devices[16];
    EGLint count = 0;
    if (api.query_devices(16, devices, &count) == EGL_TRUE) {
      for (EGLint i = 0; i < count; ++i) {
        const char* extensions = api.query_device_string(devices[i], EGL_EXTENSIONS);
        if (has_extension(extensions, "EGL_MESA_device_software")) continue;
        EGLDisplay display = api.get_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
        if (display != EGL_NO_DISPLAY) candidates.push_back({"device", display});
      }
    }
  }
  if (has_extension(client, "EGL_MESA_platform_surfaceless")) {
    EGLDisplay display =
        api.get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display != EGL_NO_DISPLAY) candidates.push_back({"surfaceless", display});
  }
  return candidates;
}

// A 3.3 core context on `display`, or EGL_NO_CONTEXT with `why` set.
EGLContext core_context(EGLDisplay display, std::string& why) {
  const auto& api = egl();
  EGLint major = 0, minor = 0;
  if (api.initialize(display, &major, &minor) != EGL_TRUE) {
    why = "eglInitialize failed (" + egl_error() + ")";
    return EGL_NO_CONTEXT;
  }
  const EGLint config_attributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                      EGL_OPENGL_BIT, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint configs = 0;
  if (api.choose_config(display, config_attributes, &config, 1, &configs) != EGL_TRUE ||
      configs < 1) {
    why = "no EGL config renders desktop OpenGL";
    return EGL_NO_CONTEXT;
  }
  if (api.bind_api(EGL_OPENGL_API) != EGL_TRUE) {
    why = "eglBindAPI(EGL_OPENGL_API) failed";
    return EGL_NO_CONTEXT;
  }
  const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                       3,
                                       EGL_CONTEXT_MINOR_VERSION,
                                       3,
                                       EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                       EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                       EGL_NONE};
  EGLContext context = api.create_context(display, config, EGL_NO_CONTEXT, context_attributes);
  if (context == EGL_NO_CONTEXT) why = "no OpenGL 3.3 core context (" + egl_error() + ")";
  return context;
}

}  // namespace

EglContext::EglContext(int width, int height) {
  const auto candidates = candidate_displays();
  if (candidates.empty())
    throw GlUnavailable(
        "EGL offers neither a GPU device nor Mesa's surfaceless platform; install the "
        "Debian package libegl-mesa0");
  std::string failures;
  for (const auto& candidate : candidates) {
    std::string why;
    EGLContext context = core_context(candidate.display, why);
    if (context != EGL_NO_CONTEXT) {
      display_ = candidate.display;
      context_ = context;
      platform_ = candidate.platform;
      break;
    }
    failures += (failures.empty() ? "" : "; ") + candidate.platform + ": " + why;
  }
  if (context_ == nullptr) throw GlUnavailable("EGL cannot create a context: " + failures);
  try {
    resize(width, height);
  } catch (...) {
    egl().destroy_context(display_, context_);
    throw;
  }
}

EglContext::~EglContext() {
  if (context_ == nullptr) return;
  // The display is shared by every context on it and is not terminated.
  if (egl().get_current_context() == context_)
    egl().make_current(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  egl().destroy_context(display_, context_);
}

void EglContext::make_current() {
  // The client API is per thread, and a context may be made current on a
  // thread other than the one that created it.
  egl().bind_api(EGL_OPENGL_API);
  if (egl().make_current(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_) != EGL_TRUE)
    throw std::runtime_error("eglMakeCurrent failed (" + egl_error() + ")");
  load_gl_functions("egl", egl_proc);
}

void EglContext::resize(int width, int height) {
  if (width <= 0 || height <= 0)
    throw std::invalid_argument("GL surface size must be positive, got " + std::to_string(width) +
                                "x" + std::to_string(height));
  // No surface to resize: the size is what callers asked for, for their FBOs.
  width_ = width;
  height_ = height;
  make_current();
}

}  // namespace epviz::render
