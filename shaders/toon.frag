#version 430 core
// Main pass: toon shading of one material. The stages of the look live in
// modules: the surface (colour and normal), lighting (bands, ramps,
// highlights, cast shadows), stylize (rim, halftone) and contour lines.
// Each module's head lists the #defines (chosen by the pass plan) it reads;
// besides those, MODE_FLAT shows the surface colour unlit, and ALPHA_MASK
// (glTF alphaMode MASK) draws nothing below the material's alpha cutoff,
// and ALPHA_BLEND (alphaMode BLEND) writes the material's alpha for the
// pass to blend over what was drawn before.
// An unlit material (glTF KHR_materials_unlit) is drawn with MODE_FLAT in
// place of the request's mode, its other variants kept. LINES_ONLY (the
// lines layer) writes the contour alone; the shading left unused is not
// compiled in. Everything is linear; the sRGB framebuffer encodes on write.
in vec3 v_position;
in vec3 v_normal;
in vec2 v_texcoord;
in vec4 v_tangent;
in vec3 v_color;

#include "view.glsl"
#include "toon_surface.glsl"
#include "toon_lighting.glsl"
#include "toon_stylize.glsl"
#include "toon_contour.glsl"

layout(location = 0) out vec4 o_color;

void main() {
#ifdef ALPHA_MASK
  if (masked_out(v_texcoord)) discard;
#endif
#ifdef ALPHA_BLEND
  float alpha = material_alpha(v_texcoord);
  // Nothing at all: neither colour nor the stencil mark the hull keeps out of.
  if (alpha < 1.0 / 255.0) discard;
#else
  float alpha = 1.0;
#endif
  vec3 albedo = surface_albedo();
#ifdef MODE_FLAT
  vec3 color = apply_halftone(albedo, albedo, 1.0);
  // Unlit, a face's side does not matter: the contour sees either side.
  float n_dot_v = abs(dot(normalize(v_normal), toward_viewer(v_position)));
#else
  vec3 n = surface_normal();
  vec3 v = toward_viewer(v_position);
  Lighting lit = light_surface(n, v);
  vec3 color = apply_rim(lit_color(albedo, lit), n, v, lit.any_lit);
  color = apply_halftone(color, albedo, lit.level);
  float n_dot_v = dot(n, v);
#endif
#ifdef LINES_ONLY
  o_color = contour_alone(n_dot_v);
#else
  o_color = vec4(apply_contour(color, n_dot_v), alpha);
#endif
}
