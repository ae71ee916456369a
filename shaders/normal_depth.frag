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

uniform vec3 u_eye;
uniform vec3 u_view_dir;
uniform int u_orthographic;

layout(location = 0) out vec4 o_normal_depth;
layout(location = 1) out float o_coverage;  // written with one sample; the resolve counts samples

#ifdef ALPHA_MASK
// Masked materials (glTF alphaMode MASK): the same alpha test as the main
// pass, so nothing lands where it drew nothing (render/passes/alpha_mask.h
// sets these; an opaque material's cutoff is one nothing fails).
uniform sampler2D u_mask_map;
uniform int u_mask_has_texture;
uniform float u_mask_opacity;
uniform float u_mask_cutoff;

bool masked_out(vec2 uv) {
  float alpha = u_mask_opacity * (u_mask_has_texture != 0 ? texture(u_mask_map, uv).a : 1.0);
  return alpha < u_mask_cutoff;
}
#endif

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
