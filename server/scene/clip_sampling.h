#pragma once
// A clip's channels read at a time: the keys around it and the
// interpolation its sampler names (glTF 2.0 §3.11 and its Appendix C).
#include <span>

#include "scene/rig.h"

namespace toond::scene {

// `time` (seconds, any value) on the clip's loop: wrapped into
// [0, duration) as clips loop; a clip of zero duration is always at 0.
double clip_time(const Clip& clip, double time);

// The channel's value at `time`, channel.width numbers into `out`. Before
// the first key the first value holds, after the last the last. LINEAR
// rotations take the shorter way round (slerp) and every rotation comes
// out of unit length; CUBICSPLINE tangents are scaled by the key interval.
void sample_channel(const Channel& channel, double time, std::span<double> out);

}  // namespace toond::scene
