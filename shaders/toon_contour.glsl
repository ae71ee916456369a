// Contour lines drawn by the shading itself where the surface turns away
// from the viewer (N·V near zero): the outline part of the main pass.
//
// Variants: CONTOUR_EVEN | CONTOUR_FRESNEL
#include "frame_shading.glsl"

vec3 apply_contour(vec3 color, float n_dot_v) {
#if defined(CONTOUR_EVEN)
  // N·V divided by how fast it changes per pixel is the distance to the
  // N·V = 0 line in pixels: a line of even width however steeply the
  // surface turns.
  if (n_dot_v < u_contour_width * fwidth(n_dot_v)) color = u_contour_color;
#elif defined(CONTOUR_FRESNEL)
  if (n_dot_v < u_contour_threshold) color = u_contour_color;
#endif
  return color;
}
