#pragma once
// A headless OpenGL core context through EGL, with no window system.
//
// Device choice: EGL devices are enumerated (EGL_EXT_device_enumeration); a
// hardware device is preferred (NVIDIA's EGL exposes its GPUs this way), and
// when there is none the context comes from Mesa's surfaceless platform
// (llvmpipe). `device_index` forces one enumerated device, like `--gpu N`.
#include <EGL/egl.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace toond::gpu {

struct EglDeviceInfo {
  int index = 0;
  std::string extensions;  // EGL device extensions
  std::string drm_file;    // DRM node, when the device has one
  bool software = false;   // EGL_MESA_device_software
};

struct GlInfo {
  std::string vendor;
  std::string renderer;
  std::string version;
  std::string glsl_version;
  std::string platform;  // "device N" or "surfaceless"
  bool robust = false;   // a lost context is reported (see reports_resets)
  int major = 0;
  int minor = 0;
};

// Whether `gl_renderer` (GL_RENDERER) names one of Mesa's CPU rasterizers
// (llvmpipe, softpipe, swrast): their "GPU" is threads of this CPU, which
// changes what is worth doing (timer queries, pixel buffer readback).
bool software_rasterizer(std::string_view gl_renderer);

class EglContext {
 public:
  struct Options {
    std::optional<int> device_index;  // nullopt: choose automatically
  };

  // Creates the display and context and makes it current on the calling
  // thread. Throws GpuError naming the EGL call and error on failure.
  explicit EglContext(const Options& options);
  ~EglContext();
  EglContext(const EglContext&) = delete;
  EglContext& operator=(const EglContext&) = delete;

  const GlInfo& info() const { return info_; }

  // Whether the driver reports a lost context through
  // glGetGraphicsResetStatus (a context made with "lose context on reset");
  // without it a reset is seen only as errors.
  bool reports_resets() const { return info_.robust; }

  // Every EGL device the driver lists (empty without device enumeration).
  static std::vector<EglDeviceInfo> enumerate_devices();

 private:
  void release();
  void read_gl_info();  // the context's vendor, renderer and versions, into info_

  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
  GlInfo info_;
};

}  // namespace toond::gpu
