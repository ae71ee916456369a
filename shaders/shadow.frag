#version 430 core
// Depth only: the fixed-function depth write is the whole output. With
// ALPHA_MASK a masked material casts no shadow where it is cut out.
in vec2 v_texcoord;

#include "material.glsl"

void main() {
#ifdef ALPHA_MASK
  if (masked_out(v_texcoord)) discard;
#endif
}
