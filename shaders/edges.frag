#version 430 core
// Screen-space edge outline over the prepass's normals and depths: a pixel
// is on an edge when its neighbours `u_reach` pixels away jump in depth by
// more than the threshold (silhouettes, intersections, parts in front of
// parts) or turn by more than the crease angle (hard edges). The depth
// threshold is a fraction of the model's size, so the test does not depend
// on how large the model is.
uniform sampler2D u_normal_depth;  // xyz normal, w distance from the eye; w = 0: background
uniform float u_reach;             // pixels: half the line width
uniform float u_depth_threshold;   // scene units
uniform float u_cos_crease;
uniform vec3 u_edge_color;         // linear

layout(location = 0) out vec4 o_color;

bool is_background(vec4 s) { return s.w <= 0.0; }

// One axis: the neighbours `r` pixels before and after. A depth jump shows
// as a second difference (a plane seen at a grazing angle changes depth
// fast, but evenly, and must not count).
// With CREASES_ONLY another pass draws the silhouette: only turns of the
// normal between two surface pixels count.
bool edge_along(vec4 c, vec4 before, vec4 after) {
#ifdef CREASES_ONLY
  if (is_background(c) || is_background(before) || is_background(after)) return false;
#else
  if (is_background(before) != is_background(c) || is_background(after) != is_background(c)) return true;
  if (is_background(c)) return false;
  if (abs(before.w + after.w - 2.0 * c.w) > u_depth_threshold) return true;
#endif
  return dot(c.xyz, before.xyz) < u_cos_crease || dot(c.xyz, after.xyz) < u_cos_crease;
}

void main() {
  ivec2 size = textureSize(u_normal_depth, 0);
  ivec2 p = ivec2(gl_FragCoord.xy);
  int r = max(int(floor(u_reach)), 1);
  vec4 c = texelFetch(u_normal_depth, p, 0);
  vec4 left = texelFetch(u_normal_depth, clamp(p - ivec2(r, 0), ivec2(0), size - 1), 0);
  vec4 right = texelFetch(u_normal_depth, clamp(p + ivec2(r, 0), ivec2(0), size - 1), 0);
  vec4 down = texelFetch(u_normal_depth, clamp(p - ivec2(0, r), ivec2(0), size - 1), 0);
  vec4 up = texelFetch(u_normal_depth, clamp(p + ivec2(0, r), ivec2(0), size - 1), 0);
  if (!edge_along(c, left, right) && !edge_along(c, down, up)) discard;
  o_color = vec4(u_edge_color, 1.0);
}
