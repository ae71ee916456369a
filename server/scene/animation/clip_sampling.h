#pragma once
// A clip's channels read at a time: the keys around it and the
// interpolation its sampler names (glTF 2.0 §3.11 and its Appendix C).
#include <span>

#include "scene/mesh/rig.h"

namespace toond::scene {

// `time` (seconds, any value) on the clip's loop: wrapped into
// [0, duration) as clips loop; a clip of zero duration is always at 0.
double clip_time(const Clip& clip, double time);

// A part of a clip's timeline, [start, end] in seconds on the file's time
// base (one action of a file that keeps every action on one timeline, as
// Minetest's player and Quake's models do). Whoever takes one from a
// request checks 0 <= start < end <= duration.
struct ClipRange {
  double start = 0;
  double end = 0;
};
ClipRange whole_clip(const Clip& clip);

// `time` counted from range.start and looped inside it: start + time
// wrapped into [0, end - start); a range of no length is always at start.
double range_time(ClipRange range, double time);

// The channel's value at `time`, channel.width numbers into `out`. Before
// the first key the first value holds, after the last the last. LINEAR
// rotations take the shorter way round (slerp) and every rotation comes
// out of unit length; CUBICSPLINE tangents are scaled by the key interval.
void sample_channel(const Channel& channel, double time, std::span<double> out);

}  // namespace toond::scene
