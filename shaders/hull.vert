#version 430 core
// Inverted-hull outline. Each vertex moves outward along its outline offset:
// the normal averaged over every vertex at the same position. With the
// shading normals, hard edges (a cube's corners) split into separate
// vertices that move apart and tear gaps in the hull (the well-known
// problem, e.g. three.js issue 19096). The offset is mitred at corners, so
// every face plane moves out by the full width.
//
// The distance is `u_width` pixels at the vertex's own depth (or, with
// u_world_units, `u_width` model units, thinning with distance like a real
// rim):
// `u_world_per_px_at_w1` is the size of one pixel at clip w = 1, and a pixel
// at depth w is w times that (w is 1 everywhere for orthographic views). A
// silhouette point's normal lies in the image plane, so there the ring is
// exactly that many pixels wide, at any distance from the camera.
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_texcoord;
layout(location = 3) in vec3 a_outline_offset;

out vec2 v_texcoord;

uniform mat4 u_view_projection;
uniform float u_world_per_px_at_w1;
uniform float u_width;        // pixels, or model units with u_world_units
uniform int u_world_units;

void main() {
  v_texcoord = a_texcoord;
  float w = (u_view_projection * vec4(a_position, 1.0)).w;
  float distance = u_world_units != 0 ? u_width : u_width * u_world_per_px_at_w1 * abs(w);
  vec3 moved = a_position + a_outline_offset * distance;
  gl_Position = u_view_projection * vec4(moved, 1.0);
}
