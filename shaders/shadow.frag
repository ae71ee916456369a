#version 430 core
// Depth only: the fixed-function depth write is the whole output. With
// ALPHA_MASK a masked material casts no shadow where it is cut out.
in vec2 v_texcoord;

#ifdef ALPHA_MASK
// The same alpha test as the main pass (render/passes/alpha_mask.h sets
// these; an opaque material's cutoff is one nothing fails).
uniform sampler2D u_mask_map;
uniform int u_mask_has_texture;
uniform float u_mask_opacity;
uniform float u_mask_cutoff;

bool masked_out(vec2 uv) {
  float alpha = u_mask_opacity * (u_mask_has_texture != 0 ? texture(u_mask_map, uv).a : 1.0);
  return alpha < u_mask_cutoff;
}
#endif

void main() {
#ifdef ALPHA_MASK
  if (masked_out(v_texcoord)) discard;
#endif
}
