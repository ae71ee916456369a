// The material a submesh is drawn with: bound per submesh from its model's
// uniform buffer (MaterialBlock in render/frame/uniform_blocks.h), and its
// textures at fixed units (render/frame/texture_unit.h).
layout(std140, binding = 3) uniform Material {
  vec3 u_base_color;  // linear
  float u_opacity;    // the base colour's alpha
  // Below this alpha nothing is drawn (a mask's cutoff; a blended
  // material's outlines, shadows and layers cut at 0.5); negative where
  // nothing is cut, so nothing fails it.
  float u_alpha_cutoff;
  int u_has_texture;
};
layout(binding = 0) uniform sampler2D u_diffuse_map;  // sRGB: sampling returns linear values
layout(binding = 2) uniform sampler2D u_normal_map;   // linear, tangent space, OpenGL convention (+Y = +V)

// Whether a masked material is cut out at `uv`: the texture's alpha cuts the
// shape (leaves, fences, hair cards) whatever colour the request gives the
// surface. Every pass that draws masked materials tests the same way, so no
// line or shadow lands where the model shows nothing.
float material_alpha(vec2 uv) { return u_opacity * (u_has_texture != 0 ? texture(u_diffuse_map, uv).a : 1.0); }

bool masked_out(vec2 uv) { return material_alpha(uv) < u_alpha_cutoff; }
