#version 430 core
// Edge prepass: the surface normal and the distance from the eye per pixel,
// for the screen-space edge pass to find creases and depth jumps in.
in vec3 v_position;
in vec3 v_normal;
in vec2 v_texcoord;

uniform vec3 u_eye;
uniform vec3 u_view_dir;
uniform int u_orthographic;

layout(location = 0) out vec4 o_normal_depth;

void main() {
  vec3 n = normalize(v_normal);
  if (!gl_FrontFacing) n = -n;
  float depth = u_orthographic != 0 ? dot(v_position - u_eye, u_view_dir) : length(v_position - u_eye);
  o_normal_depth = vec4(n, depth);
}
