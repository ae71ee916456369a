#version 430 core
// Main pass: toon shading of one material.
//
// Diffuse: N·L of each light, quantized into bands (a toon ramp), combined
// by maximum or sum; the result scales the
// material colour between the ambient floor and full brightness. Then, each
// only where its #define is set: a hard-edged Blinn-Phong highlight kept out
// of the shadow band, a rim light blended toward its colour (never added past
// it), contour lines where N·V nears zero, and a screen-space halftone.
// Everything is linear; the sRGB framebuffer encodes on write.
//
// Variants (#defines, chosen by the pass plan):
//   MODE_CEL | MODE_PHONG | MODE_FLAT      ROUND_CEIL | ROUND_FLOOR | ROUND_ROUND
//   TWO_TONE | RAMP (cel only; replace the bands)
//   BASE_WHITE   HAS_TEXTURE   VERTEX_COLOR   NORMAL_MAP   SHADE_COLOR   COMBINE_SUM   HAS_POINT_LIGHTS   SPECULAR
//   RIM (+ RIM_MASK_LIT | RIM_MASK_SHADOW)   CONTOUR_EVEN | CONTOUR_FRESNEL
//   HALFTONE_DOTS | HALFTONE_CHECKER   SHADOWS (+ SHADOW_PCF n: (2n+1)² taps)
//   BAND_AA (bands or TWO_TONE: edges blended across a pixel)
//   ALPHA_MASK (glTF alphaMode MASK: below the cutoff alpha, nothing is drawn)
// An unlit material (glTF KHR_materials_unlit) is drawn with MODE_FLAT in
// place of the request's mode, its other variants kept.
in vec3 v_position;
in vec3 v_normal;
in vec2 v_texcoord;
in vec4 v_tangent;
in vec3 v_color;

uniform vec3 u_base_color;  // material Kd, linear
uniform float u_opacity;       // ALPHA_MASK: the base colour's alpha
uniform float u_alpha_cutoff;  // ALPHA_MASK: below this alpha nothing is drawn
#ifdef SHADE_COLOR
uniform vec3 u_shade_color;  // linear: the colour of the darkest band
#endif

// Everything the frame's shading programs share, one uniform block filled
// once per frame (render/passes/shading_uniforms.cpp mirrors its std140
// layout, and ShadingBlock tests the two agree). Each variant reads what
// its features need.
layout(std140, binding = 0) uniform FrameShading {
  vec3 u_eye;  // camera position, same coordinates as v_position
  float u_ambient;
  vec3 u_view_dir;  // orthographic views: the direction the camera looks
  float u_steps;
  vec3 u_specular_color;
  float u_shininess;
  vec3 u_rim_color;
  float u_rim_power;
  vec3 u_contour_color;
  float u_contour_width;  // pixels
  vec3 u_halftone_ink;
  float u_halftone_cell;  // pixels
  float u_specular_threshold;
  float u_specular_strength;
  float u_rim_strength;
  float u_rim_threshold;
  float u_contour_threshold;  // N·V
  float u_halftone_angle;     // radians
  float u_halftone_ink_mix;
  float u_two_tone_threshold;
  float u_two_tone_shadow;
  int u_orthographic;
  vec3 u_light_vec[8];    // directional: unit vector toward the light; point: position
  vec3 u_light_color[8];  // linear colour × intensity
  int u_light_is_point[8];
  float u_light_radius[8];  // 0: unlimited
  float u_ramp_at[16];
  vec3 u_ramp_color[16];
  mat4 u_shadow_matrix;   // scene (frame) coordinates → light clip space
  int u_shadow_light;     // which light casts
  float u_shadow_texel;   // one texel in the map's [0,1] coordinates
  float u_shadow_offset;  // normal offset in scene units, against acne
};

// The number of lights is part of the program variant, not a uniform: a
// loop with a constant bound unrolls, where llvmpipe ran a uniform-bounded
// one as a masked loop with indexed array reads, much slower (toond_bench
// sweep measures the main pass).
#ifndef LIGHT_COUNT
#define LIGHT_COUNT 0
#endif

#ifdef HAS_TEXTURE
uniform sampler2D u_diffuse_map;  // sRGB texture: sampling returns linear values
#endif
#ifdef NORMAL_MAP
uniform sampler2D u_normal_map;   // linear, tangent space, OpenGL convention (+Y = +V)
#endif

#ifdef SHADOWS
uniform sampler2DShadow u_shadow_map;
#endif

layout(location = 0) out vec4 o_color;

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

#if defined(RAMP)
// Compiled in for the same reason as LIGHT_COUNT.
#ifndef RAMP_COUNT
#define RAMP_COUNT 0
#endif
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

void main() {
#ifdef ALPHA_MASK
  // glTF alphaMode MASK: the texture's alpha cuts the shape out (leaves,
  // fences, hair cards), whatever colour the request gives the surface.
  float alpha = u_opacity;
#ifdef HAS_TEXTURE
  alpha *= texture(u_diffuse_map, v_texcoord).a;
#endif
  if (alpha < u_alpha_cutoff) discard;
#endif
#ifdef BASE_WHITE
  vec3 albedo = vec3(1.0);
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
#endif

#ifdef MODE_FLAT
  vec3 color = albedo;
  float level = 1.0;
#else
  // Both faces shade like the front, so open meshes (the teapot's shells)
  // look solid from inside too.
  vec3 n = normalize(v_normal);
#ifdef NORMAL_MAP
  // Tangent-space normal map in the (tangent, bitangent, normal) frame: with
  // thresholded lighting its bumps turn into a drawn, hatched look.
  vec3 t = normalize(v_tangent.xyz - n * dot(n, v_tangent.xyz));
  vec3 b = cross(n, t) * v_tangent.w;
  vec3 mapped = texture(u_normal_map, v_texcoord).xyz * 2.0 - 1.0;
  n = normalize(mat3(t, b, n) * mapped);
#endif
  if (!gl_FrontFacing) n = -n;
  vec3 v = u_orthographic != 0 ? -u_view_dir : normalize(u_eye - v_position);

  vec3 diffuse = vec3(0.0);
  vec3 highlight = vec3(0.0);
  bool any_lit = false;
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
#ifdef SHADOWS
    // A shadowed point is quantized into the shadow band like a point
    // facing away: the (filtered) visibility is thresholded, never blended.
    if (i == u_shadow_light && n_dot_l > 0.0 && shadow_visibility(n) < 0.5) n_dot_l = -1.0;
#endif
    vec3 contribution = u_light_color[i] * ramp(n_dot_l, footprint, shadow) * reach;
    bool lit_here = !shadow && reach > 0.0;
    any_lit = any_lit || lit_here;
#ifdef COMBINE_SUM
    diffuse += contribution;
#else
    diffuse = max(diffuse, contribution);
#endif
#ifdef SPECULAR
    // Only where this light's band is above the lowest: a highlight never
    // lands in the shadow band, even for grazing lights where N·H can be
    // large while N·L is not.
    if (lit_here) {
      float s = pow(max(dot(n, normalize(l + v)), 0.0), u_shininess);
#ifdef MODE_CEL
      s = s >= u_specular_threshold ? 1.0 : 0.0;
#endif
      highlight = max(highlight, vec3(s * reach));
    }
#endif
  }
  diffuse = min(diffuse, vec3(1.0));
  // One number for "how lit": drives rim masking and the halftone.
  float level = max(diffuse.r, max(diffuse.g, diffuse.b));
#ifdef SHADE_COLOR
  // The material's own shade colour in the darkest band, blending to the
  // lit colour as the bands rise.
  vec3 color = mix(u_shade_color, albedo, diffuse);
#else
  vec3 color = albedo * (vec3(u_ambient) + (1.0 - u_ambient) * diffuse);
#endif
#ifdef SPECULAR
  color = mix(color, u_specular_color, highlight * u_specular_strength);
#endif
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
#endif  // MODE_FLAT

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

#if defined(CONTOUR_EVEN) || defined(CONTOUR_FRESNEL)
#ifndef MODE_FLAT
  float n_dot_v = dot(n, v);
#else
  vec3 nf = normalize(v_normal);
  vec3 vf = u_orthographic != 0 ? -u_view_dir : normalize(u_eye - v_position);
  float n_dot_v = abs(dot(nf, vf));
#endif
#ifdef CONTOUR_EVEN
  // N·V divided by how fast it changes per pixel is the distance to the
  // N·V = 0 line in pixels: a line of even width however steeply the
  // surface turns.
  bool on_contour = n_dot_v < u_contour_width * fwidth(n_dot_v);
#else
  bool on_contour = n_dot_v < u_contour_threshold;
#endif
  if (on_contour) color = u_contour_color;
#endif

  o_color = vec4(color, 1.0);
}
