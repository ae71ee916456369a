#version 430 core
// Crease lines (crease.geom): the points within half the outline's width
// of the edge, where both faces of the edge show. Each half of the line
// lies in its own face's plane and passes the depth test where that face
// shows; it is also dropped where the face across the edge does not show
// at the mirrored point, which the depth the main pass drew tells (the
// copy in u_scene_depth): an edge whose other face runs into a wall or
// hides behind another part, while a surface in front continues it, is no
// crease anyone sees.
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
noperspective in vec2 v_window;

// Window depth of what was drawn before the lines, one sample a pixel.
layout(binding = 0) uniform sampler2D u_scene_depth;

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
  ivec2 texel = clamp(ivec2(floor(mirror)), ivec2(0), textureSize(u_scene_depth, 0) - 1);
  float drawn = texelFetch(u_scene_depth, texel, 0).r;
  float slack = 1.5 * 0.5 * (abs(gradient.x) + abs(gradient.y)) + 8.0 / 16777216.0;
  return 0.5 * plane + 0.5 <= drawn + slack;
}

void main() {
  float half_width = 0.5 * u_width;
  if (!face_across_shows(gl_FragCoord.xy)) discard;
#ifdef SAMPLE_MASK
  int covered = 0;
  for (int k = 0; k < gl_NumSamples; ++k) {
    if (distance_to_segment(interpolateAtSample(v_window, k), v_segment_a, v_segment_b) <= half_width) {
      covered |= 1 << k;
    }
  }
  if (covered == 0) discard;
  gl_SampleMask[0] = covered;
  o_color = vec4(u_outline_color, 1.0);
#else
  float coverage = clamp(half_width - distance_to_segment(gl_FragCoord.xy, v_segment_a, v_segment_b) + 0.5, 0.0, 1.0);
  if (coverage <= 0.0) discard;
  o_color = vec4(coverage);
#endif
}
