// Contour lines drawn by the shading itself where the surface turns away
// from the viewer (N·V near zero): the outline part of the main pass.
//
// Variants: CONTOUR_EVEN | CONTOUR_FRESNEL
#include "frame_shading.glsl"

bool on_contour(float n_dot_v) {
#if defined(CONTOUR_EVEN)
  // N·V divided by how fast it changes per pixel is the distance to the
  // N·V = 0 line in pixels: a line of even width however steeply the
  // surface turns.
  return n_dot_v < u_contour_width * fwidth(n_dot_v);
#elif defined(CONTOUR_FRESNEL)
  return n_dot_v < u_contour_threshold;
#else
  return false;
#endif
}

vec3 apply_contour(vec3 color, float n_dot_v) {
  if (on_contour(n_dot_v)) color = u_contour_color;
  return color;
}

// The lines layer's share of the main pass (LINES_ONLY): the contour
// alone, premultiplied by its coverage, over transparent.
vec4 contour_alone(float n_dot_v) {
  return on_contour(n_dot_v) ? vec4(u_contour_color, 1.0) : vec4(0.0);
}
