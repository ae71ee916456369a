// The outline's look, the same for every object of a frame (OutlineBlock in
// render/frame/uniform_blocks.h).
layout(std140, binding = 4) uniform OutlineStyle {
  vec3 u_outline_color;  // linear
  float u_darken;        // per-material colours: the share taken off them
  float u_width;         // pixels (a width in world units arrives converted)
};
