// The outline's look, the same for every object of a frame (OutlineBlock in
// render/frame/uniform_blocks.h), and what the screen-space edge pass
// counts as an edge.
layout(std140, binding = 4) uniform OutlineStyle {
  vec3 u_outline_color;      // linear
  float u_darken;            // per-material colours: the share taken off them
  float u_width;             // pixels (a width in world units arrives converted)
  float u_depth_threshold;   // edge pass: a depth jump that is an edge, scene units
  float u_cos_crease;        // edge pass: normals turning further apart than this are an edge
  int u_readable_area_px;    // edge pass: 0, every edge; else only between areas that wide
  int u_whole_pixels;        // edge pass: 1, lines of whole pixels (pixel art)
};
