// What the surface is before light falls on it: its colour (material,
// texture, vertex colour, or white) and its normal (normal-mapped, and
// turned toward the viewer on back faces).
//
// Variants: BASE_WHITE   HAS_TEXTURE   VERTEX_COLOR   NORMAL_MAP
#include "material.glsl"

vec3 surface_albedo() {
#ifdef BASE_WHITE
  return vec3(1.0);
#else
  vec3 albedo = u_base_color;
#ifdef HAS_TEXTURE
  albedo *= texture(u_diffuse_map, v_texcoord).rgb;
#endif
#ifdef VERTEX_COLOR
  // Vertex colours are written like any colour picker's, sRGB-encoded.
  vec3 vc = v_color;
  albedo *= mix(vc / 12.92, pow((vc + 0.055) / 1.055, vec3(2.4)), step(0.04045, vc));
#endif
  return albedo;
#endif
}

// Both faces shade like the front, so open meshes (the teapot's shells)
// look solid from inside too.
vec3 surface_normal() {
  vec3 n = normalize(v_normal);
#ifdef NORMAL_MAP
  // Tangent-space normal map in the (tangent, bitangent, normal) frame: with
  // thresholded lighting its bumps turn into a drawn, hatched look.
  vec3 t = normalize(v_tangent.xyz - n * dot(n, v_tangent.xyz));
  vec3 b = cross(n, t) * v_tangent.w;
  vec3 mapped = texture(u_normal_map, v_texcoord).xyz * 2.0 - 1.0;
  n = normalize(mat3(t, b, n) * mapped);
#endif
  return gl_FrontFacing ? n : -n;
}
