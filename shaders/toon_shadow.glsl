// Cast shadows from the shadow map of one light.
//
// Variants: SHADOWS (+ SHADOW_PCF n: (2n+1)² taps)
#include "frame_shading.glsl"

layout(binding = 1) uniform sampler2DShadow u_shadow_map;

#ifdef SHADOWS
// Fraction of the shadow-casting light that reaches this point. The lookup
// moves out along the normal by a few texels first ("normal offset"), which
// removes self-shadowing acne on lit faces without the peter-panning a large
// constant depth bias gives.
float shadow_visibility(vec3 n) {
  vec4 p = u_shadow_matrix * vec4(v_position + n * u_shadow_offset, 1.0);
  vec3 c = p.xyz / p.w * 0.5 + 0.5;
  // Past the far plane (floor beyond the model's bounds, seen from the
  // light) is behind every occluder in the map: compare at the far plane, so
  // it is shadowed where the map holds anything and lit where it is empty.
  c.z = min(c.z, 1.0);
  float lit = 0.0;
  float taps = 0.0;
#ifdef SHADOW_PCF
  for (int y = -SHADOW_PCF; y <= SHADOW_PCF; ++y) {
    for (int x = -SHADOW_PCF; x <= SHADOW_PCF; ++x) {
      lit += texture(u_shadow_map, vec3(c.xy + vec2(x, y) * u_shadow_texel, c.z));
      taps += 1.0;
    }
  }
#else
  lit = texture(u_shadow_map, c);
  taps = 1.0;
#endif
  return lit / taps;
}
#endif

// N·L of light i as the bands should see it: a shadowed point is quantized
// into the shadow band like a point facing away (the filtered visibility
// is thresholded, never blended).
float shadowed_n_dot_l(int light, float n_dot_l, vec3 n) {
#ifdef SHADOWS
  if (light == u_shadow_light && n_dot_l > 0.0 && shadow_visibility(n) < 0.5) return -1.0;
#endif
  return n_dot_l;
}
