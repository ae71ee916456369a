#version 430 core
// Back-face wireframe outline: positions to clip space; the geometry stage
// widens each back-facing triangle's edges into screen-space quads.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_texcoord;

uniform mat4 u_view_projection;
uniform mat4 u_model;          // mesh → scene (frame) coordinates
uniform mat3 u_normal_matrix;  // inverse-transpose of u_model's 3×3
uniform vec3 u_eye;            // frame coordinates
uniform vec3 u_view_dir;       // unit
uniform int u_orthographic;

out vec2 g_texcoord;
// How much the shading normal faces the viewer (N·V): the geometry stage
// outlines a triangle only when its corners agree it is turned away.
out float g_facing;

void main() {
  g_texcoord = a_texcoord;
  vec3 position = (u_model * vec4(a_position, 1.0)).xyz;
  vec3 to_eye = u_orthographic != 0 ? -u_view_dir : normalize(u_eye - position);
  g_facing = dot(normalize(u_normal_matrix * a_normal), to_eye);
  gl_Position = u_view_projection * vec4(position, 1.0);
}
