#version 430 core
// Back-face wireframe outline: positions to clip space; the geometry stage
// widens each back-facing triangle's edges into screen-space quads.
layout(location = 0) in vec3 a_position;
layout(location = 2) in vec2 a_texcoord;

uniform mat4 u_view_projection;
uniform mat4 u_model;  // mesh → scene (frame) coordinates

out vec2 g_texcoord;

void main() {
  g_texcoord = a_texcoord;
  gl_Position = u_view_projection * (u_model * vec4(a_position, 1.0));
}
