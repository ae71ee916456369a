// How lit a point is: N·L of each light, quantized into bands (a toon
// ramp), combined by maximum or sum; a hard-edged Blinn-Phong highlight
// kept out of the shadow band. The result scales the material colour
// between the ambient floor and full brightness (or blends from the
// material's shade colour). Everything is linear.
//
// Variants: MODE_CEL | MODE_PHONG     ROUND_CEIL | ROUND_FLOOR | ROUND_ROUND
//           TWO_TONE | RAMP (cel only; replace the bands)
//           BAND_AA (bands or TWO_TONE: edges blended across a pixel)
//           COMBINE_SUM   HAS_POINT_LIGHTS   SPECULAR   SHADE_COLOR
#include "frame_shading.glsl"
#include "toon_shadow.glsl"

#ifdef SHADE_COLOR
uniform vec3 u_shade_color;  // linear: the colour of the darkest band
#endif

#if defined(MODE_CEL) && !defined(TWO_TONE) && !defined(RAMP)
// The band index for N·L × steps (band edges at integers, or at
// half-integers when rounding to nearest).
float band_of(float x) {
#if defined(ROUND_FLOOR)
  return floor(x);
#elif defined(ROUND_ROUND)
  return floor(x + 0.5);
#else
  return ceil(x);
#endif
}
#endif

// The lighting ramp: the diffuse level (or colour) for a value of N·L, and
// whether that value lies in the shadow band, the ramp's lowest step.
// `footprint` is how much N·L changes across one pixel (0: unknown); with
// BAND_AA a pixel that straddles a band edge gets the two bands mixed by
// how much of it lies on each side (a box filter of the step across the
// edge), so the edge lands at its sub-pixel position. `shadow` stays the
// hard answer: highlights and rim masks keep their crisp edges.
vec3 ramp(float n_dot_l, float footprint, out bool shadow) {
#if defined(TWO_TONE)
  shadow = n_dot_l < u_two_tone_threshold;
#ifdef BAND_AA
  if (footprint > 0.0) {
    float lit = clamp(0.5 + (n_dot_l - u_two_tone_threshold) / footprint, 0.0, 1.0);
    return vec3(mix(u_two_tone_shadow, 1.0, lit));
  }
#endif
  return vec3(shadow ? u_two_tone_shadow : 1.0);
#elif defined(RAMP)
  // Stops are sorted by `at`; below the first one there is no light.
  vec3 level = vec3(0.0);
  int step = -1;
  for (int i = 0; i < RAMP_COUNT; ++i) {
    if (n_dot_l >= u_ramp_at[i]) {
      level = u_ramp_color[i];
      step = i;
    }
  }
  shadow = step < 1;
  return level;
#elif defined(MODE_CEL)
  float x = clamp(n_dot_l, 0.0, 1.0) * u_steps;
  float b = band_of(x) / u_steps;
  shadow = b <= 0.0;
#ifdef BAND_AA
  float px = footprint * u_steps;  // band units per pixel
  if (px > 0.0) {
#if defined(ROUND_ROUND)
    float edge = floor(x) + 0.5;  // the nearest edge: half-integers
#else
    float edge = floor(x + 0.5);  // integers
#endif
    float below = band_of(clamp(edge - 0.5, 0.0, u_steps));
    float above = band_of(clamp(edge + 0.5, 0.0, u_steps));
    // Signed distance to the edge in pixels, from the unclamped N·L so the
    // terminator (N·L = 0) is smoothed too.
    float over = clamp(0.5 + (n_dot_l * u_steps - edge) / px, 0.0, 1.0);
    return vec3(mix(below, above, over) / u_steps);
  }
#endif
  return vec3(b);
#else
  shadow = n_dot_l <= 0.0;
  return vec3(max(n_dot_l, 0.0));
#endif
}

// Direction toward light i and how much of it reaches this point (0..1).
vec3 toward_light(int i, out float reach) {
  reach = 1.0;
#ifdef HAS_POINT_LIGHTS
  if (u_light_is_point[i] != 0) {
    vec3 d = u_light_vec[i] - v_position;
    float dist = length(d);
    if (u_light_radius[i] > 0.0) {
      // Full strength near the light, a smooth fade to exactly nothing at
      // the radius (no long tail, unlike 1/d²).
      float f = clamp(1.0 - pow(dist / u_light_radius[i], 4.0), 0.0, 1.0);
      reach = f * f;
    }
    return dist > 0.0 ? d / dist : vec3(0.0, 0.0, 1.0);
  }
#endif
  return u_light_vec[i];
}

// Light i's highlight at this point: only where its band is above the
// lowest, so a highlight never lands in the shadow band, even for grazing
// lights where N·H can be large while N·L is not.
float highlight_of(vec3 n, vec3 l, vec3 v, bool lit_here) {
#ifdef SPECULAR
  if (lit_here) {
#ifdef MODE_CEL
    // The highlight's threshold as an angle: no power in every pixel.
    return dot(n, normalize(l + v)) >= u_specular_min_n_dot_h ? 1.0 : 0.0;
#else
    return pow(max(dot(n, normalize(l + v)), 0.0), u_shininess);
#endif
  }
#endif
  return 0.0;
}

struct Lighting {
  vec3 diffuse;    // the ramp's levels of every light, combined, at most 1
  vec3 highlight;  // the brightest highlight
  bool any_lit;    // some light's band is above the shadow band here
  float level;     // one number for "how lit": drives rim masks and the halftone
};

Lighting light_surface(vec3 n, vec3 v) {
  Lighting lit = Lighting(vec3(0.0), vec3(0.0), false, 0.0);
  for (int i = 0; i < LIGHT_COUNT; ++i) {
    float reach;
    vec3 l = toward_light(i, reach);
    bool shadow;
    float n_dot_l = dot(n, l);
    // Taken before shadowing changes N·L: a shadow's edge is no band edge.
    float footprint = 0.0;
#ifdef BAND_AA
    footprint = length(vec2(dFdx(n_dot_l), dFdy(n_dot_l)));
#endif
    n_dot_l = shadowed_n_dot_l(i, n_dot_l, n);
    vec3 contribution = u_light_color[i] * ramp(n_dot_l, footprint, shadow) * reach;
    bool lit_here = !shadow && reach > 0.0;
    lit.any_lit = lit.any_lit || lit_here;
#ifdef COMBINE_SUM
    lit.diffuse += contribution;
#else
    lit.diffuse = max(lit.diffuse, contribution);
#endif
    lit.highlight = max(lit.highlight, vec3(highlight_of(n, l, v, lit_here) * reach));
  }
  lit.diffuse = min(lit.diffuse, vec3(1.0));
  lit.level = max(lit.diffuse.r, max(lit.diffuse.g, lit.diffuse.b));
  return lit;
}

// The surface's colour under that light.
vec3 lit_color(vec3 albedo, Lighting lit) {
#ifdef SHADE_COLOR
  // The material's own shade colour in the darkest band, blending to the
  // lit colour as the bands rise.
  vec3 color = mix(u_shade_color, albedo, lit.diffuse);
#else
  vec3 color = albedo * (vec3(u_ambient) + (1.0 - u_ambient) * lit.diffuse);
#endif
#ifdef SPECULAR
  color = mix(color, u_specular_color, lit.highlight * u_specular_strength);
#endif
  return color;
}
