// Everything the frame's shading programs share besides the camera, one
// uniform block filled once per frame (ShadingBlock in
// render/passes/shading_block.h mirrors its std140 layout, and a test checks
// the two agree). Each variant reads what its features need.
layout(std140, binding = 0) uniform FrameShading {
  float u_ambient;
  float u_steps;
  float u_shininess;
  float u_rim_power;
  vec3 u_specular_color;
  float u_contour_width;  // pixels
  vec3 u_rim_color;
  float u_halftone_cell;  // pixels
  vec3 u_contour_color;
  float u_specular_min_n_dot_h;  // cel: where (N·H)^shininess reaches the threshold
  vec3 u_halftone_ink;
  float u_specular_strength;
  float u_rim_strength;
  float u_rim_threshold;
  float u_contour_threshold;  // N·V
  float u_halftone_angle;     // radians
  float u_halftone_ink_mix;
  float u_two_tone_threshold;
  float u_two_tone_shadow;
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

// The number of lights and of ramp stops are part of the program variant,
// not uniforms: a loop with a constant bound unrolls, where llvmpipe ran a
// uniform-bounded one as a masked loop with indexed array reads, much
// slower (the main pass's time in toond_bench's sweep shows it).
#ifndef LIGHT_COUNT
#define LIGHT_COUNT 0
#endif
#ifndef RAMP_COUNT
#define RAMP_COUNT 0
#endif
