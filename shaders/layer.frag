#version 430 core
// The data layers a compositor asks for instead of the finished colour
// (output depth, normal or id): one float value set per pixel, no shading.
// The pixel's fourth channel is 1 where the model covers it; the target is
// cleared to 0, which marks the background.
//
// Variants: LAYER_DEPTH | LAYER_NORMAL | LAYER_ID, ALPHA_MASK
in vec3 v_position;
in vec3 v_normal;
in vec2 v_texcoord;

#include "view.glsl"
#include "material.glsl"

// Frame coordinates to view space (x right, y up, z toward the viewer).
uniform mat3 u_view_rotation;
uniform float u_layer_id;  // LAYER_ID: this draw's index (1 and up)

layout(location = 0) out vec4 o_layer;
layout(location = 1) out float o_coverage;

void main() {
#ifdef ALPHA_MASK
  if (masked_out(v_texcoord)) discard;
#endif
#if defined(LAYER_DEPTH)
  // Linear depth along the view axis (not the distance from the eye): a
  // plane facing the camera has one depth in either projection.
  o_layer = vec4(dot(v_position - u_eye, u_view_dir), 0.0, 0.0, 1.0);
#elif defined(LAYER_NORMAL)
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  o_layer = vec4(normalize(u_view_rotation * n), 1.0);
#elif defined(LAYER_ID)
  o_layer = vec4(u_layer_id, 0.0, 0.0, 1.0);
#endif
  o_coverage = 1.0;
}
