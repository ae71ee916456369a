#include "scene/animation/clip_sampling.h"

#include <algorithm>
#include <cmath>

namespace toond::scene {
namespace {

// Key k's value (CUBICSPLINE: its middle group), component c.
double key_value(const Channel& ch, std::size_t k, int c) {
  const std::size_t groups = ch.interpolation == Interpolation::CubicSpline ? 3 : 1;
  const std::size_t middle = ch.interpolation == Interpolation::CubicSpline ? 1 : 0;
  return ch.values[(k * groups + middle) * static_cast<std::size_t>(ch.width) + static_cast<std::size_t>(c)];
}

// A CUBICSPLINE key's in-tangent (group 0) or out-tangent (group 2).
double key_tangent(const Channel& ch, std::size_t k, int group, int c) {
  return ch.values[(k * 3 + static_cast<std::size_t>(group)) * static_cast<std::size_t>(ch.width) +
                   static_cast<std::size_t>(c)];
}

void normalise_rotation(std::span<double> q) {
  const double length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (!(length > 0.0) || !std::isfinite(length)) {
    q[0] = q[1] = q[2] = 0.0;
    q[3] = 1.0;
    return;
  }
  for (double& v : q) v /= length;
}

// Spherical interpolation of key a's and key b's rotations by `s`, the
// shorter way: q and -q are one rotation, and the file may store either.
void slerp_keys(const Channel& ch, std::size_t a, std::size_t b, double s, std::span<double> out) {
  const glm::dquat qa(key_value(ch, a, 3), key_value(ch, a, 0), key_value(ch, a, 1), key_value(ch, a, 2));
  glm::dquat qb(key_value(ch, b, 3), key_value(ch, b, 0), key_value(ch, b, 1), key_value(ch, b, 2));
  const glm::dquat na = glm::normalize(qa);
  glm::dquat nb = glm::normalize(qb);
  if (glm::dot(na, nb) < 0.0) nb = -nb;
  const glm::dquat q = glm::slerp(na, nb, s);
  out[0] = q.x;
  out[1] = q.y;
  out[2] = q.z;
  out[3] = q.w;
  normalise_rotation(out);
}

}  // namespace

double clip_time(const Clip& clip, double time) {
  if (!(clip.duration > 0.0) || !std::isfinite(time)) return 0.0;
  const double wrapped = std::fmod(time, clip.duration);
  return wrapped < 0.0 ? wrapped + clip.duration : wrapped;
}

ClipRange whole_clip(const Clip& clip) { return {0.0, clip.duration}; }

double range_time(ClipRange range, double time) {
  const double length = range.end - range.start;
  if (!(length > 0.0) || !std::isfinite(time)) return range.start;
  const double wrapped = std::fmod(time, length);
  return range.start + (wrapped < 0.0 ? wrapped + length : wrapped);
}

void sample_channel(const Channel& ch, double time, std::span<double> out) {
  const std::size_t keys = ch.times.size();
  const bool rotation = ch.path == ChannelPath::Rotation;
  // The first key after `time`: the interval is [next - 1, next].
  const std::size_t next =
      static_cast<std::size_t>(std::upper_bound(ch.times.begin(), ch.times.end(), time) - ch.times.begin());
  if (next == 0 || next == keys || ch.interpolation == Interpolation::Step) {
    const std::size_t k = next == 0 ? 0 : next - 1;
    for (int c = 0; c < ch.width; ++c) out[static_cast<std::size_t>(c)] = key_value(ch, k, c);
    if (rotation) normalise_rotation(out);
    return;
  }
  const std::size_t a = next - 1, b = next;
  const double interval = ch.times[b] - ch.times[a];
  const double s = (time - ch.times[a]) / interval;
  if (ch.interpolation == Interpolation::Linear) {
    if (rotation) return slerp_keys(ch, a, b, s, out);
    for (int c = 0; c < ch.width; ++c) {
      out[static_cast<std::size_t>(c)] = key_value(ch, a, c) + s * (key_value(ch, b, c) - key_value(ch, a, c));
    }
    return;
  }
  // Cubic Hermite between the keys' values with their out- and
  // in-tangents, which are per second: scaled by the interval.
  const double s2 = s * s, s3 = s2 * s;
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2, h11 = s3 - s2;
  for (int c = 0; c < ch.width; ++c) {
    out[static_cast<std::size_t>(c)] = h00 * key_value(ch, a, c) + h10 * interval * key_tangent(ch, a, 2, c) +
                                       h01 * key_value(ch, b, c) + h11 * interval * key_tangent(ch, b, 0, c);
  }
  if (rotation) normalise_rotation(out);
}

}  // namespace toond::scene
