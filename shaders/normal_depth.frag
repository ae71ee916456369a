#version 430 core
// Edge prepass: per sample, the surface normal and the distance from the
// eye, and full coverage, for the screen-space edge pass to find
// silhouettes, creases and depth jumps in. Background stays all zero.
// Multisampled, a triangle covering some of a pixel's samples but not its
// centre would otherwise write values extrapolated past its edge, and a
// silhouette pixel would read as a depth jump.
centroid in vec3 v_position;
centroid in vec3 v_normal;
in vec2 v_texcoord;

#include "view.glsl"
#include "material.glsl"

layout(location = 0) out vec4 o_normal_depth;
layout(location = 1) out float o_coverage;  // written with one sample; the resolve counts samples

void main() {
#ifdef ALPHA_MASK
  if (masked_out(v_texcoord)) discard;
#endif
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  float depth = u_orthographic != 0 ? dot(v_position - u_eye, u_view_dir) : length(v_position - u_eye);
  o_normal_depth = vec4(n, depth);
  o_coverage = 1.0;
}
