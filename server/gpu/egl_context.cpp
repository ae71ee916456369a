#include "gpu/egl_context.h"

#include <EGL/eglext.h>

#include <cstring>
#include <string_view>
#include <vector>

#include "gpu/gl.h"
#include "gpu/gpu_error.h"

namespace toond::gpu {

bool software_rasterizer(std::string_view gl_renderer) {
  for (std::string_view software : {"llvmpipe", "softpipe", "swrast"}) {
    if (gl_renderer.find(software) != std::string_view::npos) return true;
  }
  return false;
}
namespace {

const char* egl_error_name(EGLint error) {
  switch (error) {
    case EGL_SUCCESS:
      return "EGL_SUCCESS";
    case EGL_NOT_INITIALIZED:
      return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
      return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
      return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
      return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
      return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
      return "EGL_BAD_CONTEXT";
    case EGL_BAD_CURRENT_SURFACE:
      return "EGL_BAD_CURRENT_SURFACE";
    case EGL_BAD_DISPLAY:
      return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
      return "EGL_BAD_MATCH";
    case EGL_BAD_NATIVE_PIXMAP:
      return "EGL_BAD_NATIVE_PIXMAP";
    case EGL_BAD_NATIVE_WINDOW:
      return "EGL_BAD_NATIVE_WINDOW";
    case EGL_BAD_PARAMETER:
      return "EGL_BAD_PARAMETER";
    case EGL_BAD_SURFACE:
      return "EGL_BAD_SURFACE";
    case EGL_CONTEXT_LOST:
      return "EGL_CONTEXT_LOST";
    default:
      return "unknown EGL error";
  }
}

[[noreturn]] void fail(const std::string& what) {
  throw GpuError("EglContext: " + what + " failed: " + egl_error_name(eglGetError()));
}

bool has_extension(const char* list, std::string_view name) {
  if (!list) return false;
  std::string_view all(list);
  for (std::size_t pos = 0; pos < all.size();) {
    std::size_t end = all.find(' ', pos);
    if (end == std::string_view::npos) end = all.size();
    if (all.substr(pos, end - pos) == name) return true;
    pos = end + 1;
  }
  return false;
}

template <class Fn>
Fn egl_proc(const char* name) {
  return reinterpret_cast<Fn>(eglGetProcAddress(name));
}

std::vector<EGLDeviceEXT> query_devices() {
  const char* client_extensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!has_extension(client_extensions, "EGL_EXT_device_enumeration") &&
      !has_extension(client_extensions, "EGL_EXT_device_base")) {
    return {};
  }
  auto query = egl_proc<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
  if (!query) return {};
  EGLint count = 0;
  if (!query(0, nullptr, &count) || count <= 0) return {};
  std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
  if (!query(count, devices.data(), &count)) return {};
  devices.resize(static_cast<std::size_t>(count));
  return devices;
}

EglDeviceInfo describe(EGLDeviceEXT device, int index) {
  auto query_string = egl_proc<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
  EglDeviceInfo info;
  info.index = index;
  if (query_string) {
    if (const char* ext = query_string(device, EGL_EXTENSIONS)) info.extensions = ext;
    if (has_extension(info.extensions.c_str(), "EGL_EXT_device_drm")) {
      if (const char* file = query_string(device, EGL_DRM_DEVICE_FILE_EXT)) info.drm_file = file;
    }
  }
  info.software = has_extension(info.extensions.c_str(), "EGL_MESA_device_software");
  return info;
}

EGLDisplay platform_display(EGLenum platform, void* native) {
  auto get_display = egl_proc<PFNEGLGETPLATFORMDISPLAYEXTPROC>("eglGetPlatformDisplayEXT");
  if (!get_display) return EGL_NO_DISPLAY;
  return get_display(platform, native, nullptr);
}

}  // namespace

std::vector<EglDeviceInfo> EglContext::enumerate_devices() {
  std::vector<EglDeviceInfo> out;
  const auto devices = query_devices();
  for (std::size_t i = 0; i < devices.size(); ++i) {
    out.push_back(describe(devices[i], static_cast<int>(i)));
  }
  return out;
}

namespace {

struct OpenedDisplay {
  EGLDisplay display = EGL_NO_DISPLAY;
  std::string platform;  // GlInfo::platform
};

// The EGL device `index` names (--gpu).
OpenedDisplay display_of_device(const std::vector<EGLDeviceEXT>& devices, int index) {
  if (index < 0 || static_cast<std::size_t>(index) >= devices.size()) {
    throw GpuError("EglContext: --gpu " + std::to_string(index) + " asked for, but EGL lists " +
                   std::to_string(devices.size()) + " device(s)");
  }
  return {platform_display(EGL_PLATFORM_DEVICE_EXT, devices[static_cast<std::size_t>(index)]),
          "device " + std::to_string(index)};
}

// The first hardware device that initialises; a hardware device that will
// not is skipped, not fatal. None: EGL_NO_DISPLAY.
OpenedDisplay first_hardware_display(const std::vector<EGLDeviceEXT>& devices) {
  for (std::size_t i = 0; i < devices.size(); ++i) {
    if (describe(devices[i], static_cast<int>(i)).software) continue;
    const EGLDisplay display = platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i]);
    if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) {
      return {display, "device " + std::to_string(i)};
    }
  }
  return {};
}

// The device --gpu names; else the first hardware device; else Mesa's
// surfaceless platform (llvmpipe).
OpenedDisplay open_display(const EglContext::Options& options) {
  const auto devices = query_devices();
  if (options.device_index) return display_of_device(devices, *options.device_index);
  OpenedDisplay opened = first_hardware_display(devices);
  if (opened.display != EGL_NO_DISPLAY) return opened;
  if (!has_extension(eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS), "EGL_MESA_platform_surfaceless")) {
    throw GpuError(
        "EglContext: no hardware EGL device and no EGL_MESA_platform_surfaceless "
        "(install Mesa's libegl-mesa0 or a GPU driver)");
  }
  return {platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY), "surfaceless"};
}

// No surface is ever made (EGL_KHR_surfaceless_context); the config only
// has to be one that can create a desktop GL context. eglChooseConfig
// defaults EGL_SURFACE_TYPE to windows, which a headless display may have
// none of: ask for pbuffer-capable configs, then for any.
EGLConfig choose_config(EGLDisplay display) {
  EGLConfig config = nullptr;
  EGLint config_count = 0;
  for (EGLint surface_type : {EGL_PBUFFER_BIT, 0}) {
    const EGLint config_attribs[] = {EGL_SURFACE_TYPE, surface_type, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    if (eglChooseConfig(display, config_attribs, &config, 1, &config_count) && config_count > 0) return config;
  }
  fail("eglChooseConfig(OpenGL)");
}

// Where the display can, the context is made robust with "lose context on
// reset", so a GPU reset is reported (glGetGraphicsResetStatus) and the
// render thread can start over instead of drawing into a dead context.
// Desktop GL names the strategy through EGL 1.5 / EGL_KHR_create_context;
// EGL_EXT_create_context_robustness has its own token. 0: a plain context.
std::vector<EGLint> reset_strategy_names(EGLDisplay display, EGLint egl_major, EGLint egl_minor) {
  const std::string extensions = eglQueryString(display, EGL_EXTENSIONS);
  std::vector<EGLint> names;
  if (egl_major > 1 || (egl_major == 1 && egl_minor >= 5) ||
      has_extension(extensions.c_str(), "EGL_KHR_create_context")) {
    names.push_back(EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY);
  }
  if (has_extension(extensions.c_str(), "EGL_EXT_create_context_robustness")) {
    names.push_back(EGL_CONTEXT_OPENGL_RESET_NOTIFICATION_STRATEGY_EXT);
  }
  names.push_back(0);
  return names;
}

struct CreatedContext {
  EGLContext context = EGL_NO_CONTEXT;
  bool robust = false;
};

// Newest core version first; 4.3 is the floor (compute, debug output,
// SSBOs); robust where the display can make it so.
CreatedContext create_context(EGLDisplay display, EGLConfig config, EGLint egl_major, EGLint egl_minor) {
  static constexpr int versions[][2] = {{4, 6}, {4, 5}, {4, 4}, {4, 3}};
  for (const EGLint strategy : reset_strategy_names(display, egl_major, egl_minor)) {
    for (const auto& v : versions) {
      const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                        v[0],
                                        EGL_CONTEXT_MINOR_VERSION,
                                        v[1],
                                        EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                        strategy != 0 ? strategy : EGL_NONE,
                                        EGL_LOSE_CONTEXT_ON_RESET,
                                        EGL_NONE};
      const EGLContext context = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attribs);
      if (context != EGL_NO_CONTEXT) return {context, strategy != 0};
    }
  }
  fail("eglCreateContext(OpenGL core >= 4.3)");
}

std::string gl_string(GLenum name) {
  const auto* s = reinterpret_cast<const char*>(glGetString(name));
  return std::string(s ? s : "");
}

// toond uses direct state access throughout: core in 4.5, an extension before.
bool has_direct_state_access(const GlInfo& info) {
  if (info.major > 4 || (info.major == 4 && info.minor >= 5)) return true;
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i) {
    const auto* ext = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
    if (ext && std::strcmp(ext, "GL_ARB_direct_state_access") == 0) return true;
  }
  return false;
}

}  // namespace

EglContext::EglContext(const Options& options) {
  OpenedDisplay opened = open_display(options);
  display_ = opened.display;
  info_.platform = std::move(opened.platform);
  if (display_ == EGL_NO_DISPLAY) fail("eglGetPlatformDisplayEXT");
  EGLint egl_major = 0, egl_minor = 0;
  if (!eglInitialize(display_, &egl_major, &egl_minor)) fail("eglInitialize");
  if (!eglBindAPI(EGL_OPENGL_API)) fail("eglBindAPI(EGL_OPENGL_API)");
  const CreatedContext created = create_context(display_, choose_config(display_), egl_major, egl_minor);
  context_ = created.context;
  info_.robust = created.robust;
  if (!eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
    eglDestroyContext(display_, context_);
    context_ = EGL_NO_CONTEXT;
    fail("eglMakeCurrent(surfaceless)");
  }
  read_gl_info();
  if (!has_direct_state_access(info_)) {
    release();
    throw GpuError("EglContext: OpenGL " + info_.version +
                   " lacks direct state access (needs 4.5 or GL_ARB_direct_state_access)");
  }
}

void EglContext::read_gl_info() {
  info_.vendor = gl_string(GL_VENDOR);
  info_.renderer = gl_string(GL_RENDERER);
  info_.version = gl_string(GL_VERSION);
  info_.glsl_version = gl_string(GL_SHADING_LANGUAGE_VERSION);
  glGetIntegerv(GL_MAJOR_VERSION, &info_.major);
  glGetIntegerv(GL_MINOR_VERSION, &info_.minor);
}

EglContext::~EglContext() { release(); }

void EglContext::release() {
  if (display_ == EGL_NO_DISPLAY) return;
  // A context that is still current when destroyed lingers until released;
  // un-current it first so the driver frees it now.
  eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
  // No eglTerminate: EGL hands every caller asking for the same device the
  // same display, so terminating it here would pull the display out from
  // under any other context made on it. It lives as long as the process.
  display_ = EGL_NO_DISPLAY;
  context_ = EGL_NO_CONTEXT;
}

}  // namespace toond::gpu
