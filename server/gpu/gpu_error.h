#pragma once
#include <stdexcept>
#include <string>

namespace toond::gpu {

// A failure of EGL or GL at run time (no device, context lost, shader that
// does not compile, framebuffer incomplete). The request fails with a 5xx;
// the daemon goes on.
class GpuError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The GL context was lost (a GPU reset, a driver restart). The render that
// saw it fails; the render thread makes a new context and uploads models
// again as they are used, so a retry succeeds.
class GpuReset : public GpuError {
 public:
  using GpuError::GpuError;
};

}  // namespace toond::gpu
