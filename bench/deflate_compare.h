#pragma once
// zlib against libdeflate on one frame's Sub-filtered scanlines, whole and
// on one thread, at one level: what issue 30 asks to measure before any
// encoder code is written for libdeflate.
#include "image/image.h"

namespace toond::bench {

// Prints one line: the median time and size of each library's zlib stream.
void compare_deflaters(const char* name, const image::Image& frame, int level, int repeats);

}  // namespace toond::bench
