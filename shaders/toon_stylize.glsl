// Looks drawn over the lit colour: a rim light blended toward its colour
// (never added past it) and a screen-space halftone.
//
// Variants: RIM (+ RIM_MASK_LIT | RIM_MASK_SHADOW)   HALFTONE_DOTS | HALFTONE_CHECKER
#include "frame_shading.glsl"

vec3 apply_rim(vec3 color, vec3 n, vec3 v, bool any_lit) {
#ifdef RIM
  float rim = pow(1.0 - clamp(dot(n, v), 0.0, 1.0), u_rim_power);
  if (u_rim_threshold > 0.0) rim = rim >= u_rim_threshold ? 1.0 : 0.0;
#if defined(RIM_MASK_LIT)
  rim *= any_lit ? 1.0 : 0.0;
#elif defined(RIM_MASK_SHADOW)
  rim *= any_lit ? 0.0 : 1.0;
#endif
  // A blend, not an addition: the rim can reach its colour but never
  // overshoot it, so a rim cannot wash the model out.
  color = mix(color, u_rim_color, rim * u_rim_strength);
#endif
  return color;
}

// `level` is how lit the point is (0..1).
vec3 apply_halftone(vec3 color, vec3 albedo, float level) {
#if defined(HALFTONE_DOTS) || defined(HALFTONE_CHECKER)
  vec2 c = gl_FragCoord.xy;
  float ca = cos(u_halftone_angle), sa = sin(u_halftone_angle);
  vec2 cell = vec2(ca * c.x + sa * c.y, -sa * c.x + ca * c.y) / u_halftone_cell;
  vec3 shadow_tone = mix(albedo * u_ambient, u_halftone_ink, u_halftone_ink_mix);
#ifdef HALFTONE_DOTS
  // True halftone: two tones only, the fully lit colour and dots of the
  // shadow tone whose area grows as the light falls. A dot covering the
  // fraction (1 - level) of its cell has radius sqrt((1 - level) / π) cells.
  float dot_radius = sqrt(max(1.0 - level, 0.0) / 3.14159265);
  float in_dot = length(fract(cell) - 0.5) < dot_radius ? 1.0 : 0.0;
  vec3 lit_tone = color + albedo * (1.0 - u_ambient) * (1.0 - level);
  color = mix(lit_tone, shadow_tone, in_dot);
#else
  // The cheap approximation: in the mid bands only, alternate cells of a
  // checkerboard between the lit colour and the shadow tone.
  if (level > 0.0 && level < 1.0) {
    vec2 k = floor(cell);
    if (mod(k.x + k.y, 2.0) < 1.0) color = shadow_tone;
    else color = albedo;
  }
#endif
#endif
  return color;
}
