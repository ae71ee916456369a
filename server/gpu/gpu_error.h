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

}  // namespace toond::gpu
