#version 430 core
// Outline colour: the stencil test leaves only the ring outside the model.
// Variants: fixed colour (default), OUTLINE_MATERIAL (the material colour
// darkened), OUTLINE_TEXTURE (the texture under the line, inverted and
// darkened, as the reference viewer drew textured outlines).
in vec2 v_texcoord;

uniform vec3 u_outline_color;  // linear
#if defined(OUTLINE_MATERIAL) || defined(OUTLINE_TEXTURE)
uniform vec3 u_base_color;
uniform float u_darken;
#endif
#ifdef OUTLINE_TEXTURE
uniform int u_has_texture;
uniform sampler2D u_diffuse_map;
#endif

layout(location = 0) out vec4 o_color;

void main() {
#if defined(OUTLINE_TEXTURE)
  vec3 source = u_has_texture != 0 ? vec3(1.0) - texture(u_diffuse_map, v_texcoord).rgb * u_base_color
                                   : u_base_color;
  o_color = vec4(source * (1.0 - u_darken), 1.0);
#elif defined(OUTLINE_MATERIAL)
  o_color = vec4(u_base_color * (1.0 - u_darken), 1.0);
#else
  o_color = vec4(u_outline_color, 1.0);
#endif
}
