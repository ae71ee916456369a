#pragma once
// How long one pass of a render took: what the Server-Timing header and the
// metrics report, filled in by PassTimer.
#include <string>

namespace toond::render {

struct PassTiming {
  std::string pass;
  double ms = 0;      // GPU time where `gpu`, else CPU wall time for issuing + (for readback) waiting
  bool gpu = false;   // from a GL_TIME_ELAPSED query
  double cpu_ms = 0;  // wall time on the render thread, always
};

}  // namespace toond::render
