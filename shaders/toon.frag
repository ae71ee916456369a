#version 430 core
// Main pass: cel shading. The diffuse term N·L of each light is quantized
// into bands (the "toon ramp" of the reference reports), lights are combined
// by maximum, and the result scales the material colour between the ambient
// floor and full brightness. Everything is linear; the sRGB framebuffer
// encodes on write.
//
// Variants (#defines): MODE_CEL | MODE_PHONG | MODE_FLAT,
// ROUND_CEIL | ROUND_FLOOR | ROUND_ROUND, HAS_TEXTURE.
in vec3 v_position;
in vec3 v_normal;
in vec2 v_texcoord;

uniform vec3 u_base_color;  // material Kd, linear
uniform float u_ambient;
uniform float u_steps;
uniform int u_light_count;
uniform vec3 u_light_to[8];     // unit vectors from the surface toward each light
uniform vec3 u_light_color[8];  // linear colour × intensity

#ifdef HAS_TEXTURE
uniform sampler2D u_diffuse_map;  // sRGB texture: sampling returns linear values
#endif

layout(location = 0) out vec4 o_color;

float band(float n_dot_l) {
  float x = clamp(n_dot_l, 0.0, 1.0) * u_steps;
#if defined(ROUND_FLOOR)
  return floor(x) / u_steps;
#elif defined(ROUND_ROUND)
  return floor(x + 0.5) / u_steps;
#else
  return ceil(x) / u_steps;
#endif
}

void main() {
  vec3 albedo = u_base_color;
#ifdef HAS_TEXTURE
  albedo *= texture(u_diffuse_map, v_texcoord).rgb;
#endif

#ifdef MODE_FLAT
  o_color = vec4(albedo, 1.0);
#else
  // Both faces shade like the front, so open meshes (the teapot's shells)
  // look solid from inside too.
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;

  vec3 diffuse = vec3(0.0);
  for (int i = 0; i < u_light_count; ++i) {
    float n_dot_l = dot(n, u_light_to[i]);
#ifdef MODE_CEL
    float level = band(n_dot_l);
#else
    float level = max(n_dot_l, 0.0);
#endif
    diffuse = max(diffuse, u_light_color[i] * level);
  }
  vec3 light = vec3(u_ambient) + (1.0 - u_ambient) * diffuse;
  o_color = vec4(albedo * light, 1.0);
#endif
}
