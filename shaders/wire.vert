#version 430 core
// Back-face wireframe outline: positions to clip space; the geometry stage
// widens each back-facing triangle's edges into screen-space quads.
#include "attributes.glsl"
#include "view.glsl"
#include "object.glsl"
#include "skinning.glsl"

out vec2 g_texcoord;
// How much the shading normal faces the viewer (N·V): the geometry stage
// outlines a triangle only when its corners agree it is turned away.
out float g_facing;

void main() {
  g_texcoord = a_texcoord;
  PosedVertex posed = posed_vertex();
  vec3 position = (u_model * vec4(posed.position, 1.0)).xyz;
  g_facing = dot(normalize(u_normal_matrix * posed.normal), toward_viewer(position));
  gl_Position = u_view_projection * vec4(position, 1.0);
}
