#version 430 core
// Inverted-hull outline. Each vertex moves outward along its outline offset:
// the normal averaged over every vertex at the same position. With the
// shading normals, hard edges (a cube's corners) split into separate
// vertices that move apart and tear gaps in the hull. The offset is mitred at corners, so
// every face plane moves out by the full width.
//
// The distance is `u_width` pixels at the vertex's own depth (a width in
// world units arrives converted to pixels, render/plan/outline_width.h):
// `u_world_per_px_at_w1` (view.glsl) gives a pixel's size at each depth. A
// silhouette point's normal lies in the image plane, so there the ring is
// exactly that many pixels wide, at any distance from the camera.
#include "attributes.glsl"
#include "view.glsl"
#include "object.glsl"
#include "skinning.glsl"
#include "outline_style.glsl"

out vec2 v_texcoord;

// A pixel's size at depth w holds for a move parallel to the image. Off
// the view's axis a silhouette point's normal is perpendicular to its own
// ray, not to the axis, and a move along it shows 1/cos of the ray's angle
// longer (MessyMeshOracle.OutlineRingIsTheWidthAllRound measures it). The
// factor
// that makes the part of the offset the image can show, the part across
// the ray, exactly as long on screen as asked; 1 in orthographic views.
float obliquity_correction(vec3 position, vec4 clip, vec3 offset, float distance) {
  vec3 ray = u_orthographic != 0 ? u_view_dir : normalize(position - u_eye);
  vec3 across = offset - dot(offset, ray) * ray;
  float across_len = length(across);
  if (clip.w <= 0.0 || across_len < 1e-3 * length(offset)) return 1.0;
  vec4 moved = u_view_projection * vec4(position + across * distance, 1.0);
  if (moved.w <= 0.0) return 1.0;
  float shown_px = length((moved.xy / moved.w - clip.xy / clip.w) * 0.5 * u_viewport_px);
  float wanted_px = u_width * across_len;
  return shown_px > 0.0 ? clamp(wanted_px / shown_px, 0.5, 1.0) : 1.0;
}

void main() {
  v_texcoord = a_texcoord;
  PosedVertex posed = posed_vertex();
  vec3 position = (u_model * vec4(posed.position, 1.0)).xyz;
  // The offset turns with the surface (the normal matrix), then gets back
  // its own length, so the ring stays `u_width` wide whatever the object's
  // scale. Exact where the offset is the smooth normal (length 1) under any
  // scale, and for mitred corners (length 1/cos) under uniform scale. Under
  // non-uniform scale a hard corner's faces move out somewhat more or less
  // than `u_width` (an exact mitre would need the face normals). Scaling
  // the offset by the 3×3 instead would widen the outline of a scaled-up
  // object and tilt smooth normals off the surface.
  float len = length(posed.outline_offset);
  vec3 turned = u_normal_matrix * posed.outline_offset;
  float turned_len = length(turned);
  vec3 offset = turned_len > 0.0 ? turned * (len / turned_len) : vec3(0.0);
  vec4 clip = u_view_projection * vec4(position, 1.0);
  float distance = u_width * u_world_per_px_at_w1 * abs(clip.w);
  distance *= obliquity_correction(position, clip, offset, distance);
  vec3 moved = position + offset * distance;
  gl_Position = u_view_projection * vec4(moved, 1.0);
}
