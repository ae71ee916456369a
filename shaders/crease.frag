#version 430 core
// Crease lines (crease.geom): the points within half the outline's width
// of the edge, where both faces of the edge show. Each half of the line
// lies in its own face's plane, brought toward the viewer by that plane's
// depth change over a pixel's step, and shows where that is no farther
// than what the main pass drew (the copy in u_scene_depth, every sample of
// it): an offset by the line's own face, not a constant, which would let
// hidden creases through behind faces seen at a grazing angle and cut
// lines on steep ones. This stage does that depth test itself, sample by
// sample: a wide GL line has no depth of its own across it, and one depth
// written for a whole pixel either loses a line's samples on a steep face
// or lets a hidden line through. Every position here comes from
// gl_FragCoord, as a line's inputs vary only along it. The line is also
// dropped where the face across the edge does not show at the mirrored
// point: an edge whose other face runs into a wall or hides behind another
// part, while a surface in front continues it, is no crease anyone sees.
// Multisampled (SAMPLE_MASK), each sample is tested where it lies and
// written opaque in the outline's colour: where two lines overlap (at
// every join) they write the same samples, so nothing is darkened twice,
// and the line's border is antialiased like a triangle's. One sample a
// pixel, the share of the pixel the line covers goes to a coverage target
// that keeps the largest share any line gave the pixel (blended by MAX);
// crease_coverage.frag lays that over the image once.
flat in vec2 v_segment_a;
flat in vec2 v_segment_b;
flat in float v_depth_a;
flat in vec4 v_depth_gradients;
flat in vec2 v_toward_face1;

#include "scene_depth.glsl"
#ifdef SAMPLE_MASK
// Where each sample lies in its pixel, as the target places them
// (gpu/render_target.h); as many as gl_NumSamples, at most 16.
uniform vec2 u_sample_positions[16];
#endif

#include "outline_style.glsl"
#include "line_segment.glsl"

layout(location = 0) out vec4 o_color;

// Whether the face across the edge from `p` shows at p's mirror image
// across the edge: its plane's depth there is no farther than what was
// drawn, give or take its depth change over a pixel and a half (the
// drawn depth was taken at some sample of the pixel, not at the point).
bool face_across_shows(vec2 p) {
  float across = dot(p - v_segment_a, v_toward_face1);
  vec2 mirror = p - 2.0 * across * v_toward_face1;
  vec2 gradient = across > 0.0 ? v_depth_gradients.zw : v_depth_gradients.xy;
  float plane = v_depth_a + dot(gradient, mirror - v_segment_a);
  float drawn = scene_depth(mirror, 0);
  float slack = 1.5 * 0.5 * (abs(gradient.x) + abs(gradient.y)) + 8.0 / 16777216.0;
  return 0.5 * plane + 0.5 <= drawn + slack;
}

// Whether the line shows at `p`, sample `k` of its pixel: the plane of the
// face on p's side, brought nearer by its depth change over a pixel's step
// along x or y and a couple of the depth buffer's steps (as
// glPolygonOffset(-1, -1) would), lies no farther than what was drawn.
bool line_shows(vec2 p, int k) {
  vec2 gradient = dot(p - v_segment_a, v_toward_face1) > 0.0 ? v_depth_gradients.xy : v_depth_gradients.zw;
  float plane = 0.5 * (v_depth_a + dot(gradient, p - v_segment_a)) + 0.5;
  float step_change = 0.5 * max(abs(gradient.x), abs(gradient.y));
  return plane - step_change - 2.0 / 16777216.0 <= scene_depth(p, k);
}

void main() {
  vec2 p = gl_FragCoord.xy;
  float half_width = 0.5 * u_width;
  if (!face_across_shows(p)) discard;
#ifdef SAMPLE_MASK
  vec2 corner = floor(p);
  int covered = 0;
  for (int k = 0; k < min(gl_NumSamples, 16); ++k) {
    vec2 sample_at = corner + u_sample_positions[k];
    if (distance_to_segment(sample_at, v_segment_a, v_segment_b) <= half_width && line_shows(sample_at, k)) {
      covered |= 1 << k;
    }
  }
  if (covered == 0) discard;
  gl_SampleMask[0] = covered;
  o_color = vec4(u_outline_color, 1.0);
#else
  float coverage = clamp(half_width - distance_to_segment(p, v_segment_a, v_segment_b) + 0.5, 0.0, 1.0);
  if (coverage <= 0.0 || !line_shows(p, 0)) discard;
  o_color = vec4(coverage);
#endif
}
