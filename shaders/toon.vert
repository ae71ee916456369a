#version 430 core
// Main pass vertex stage. Positions arrive relative to the model's origin
// (recentred in double precision on the CPU), so the float maths here stays
// precise however far the model sits from its own coordinate origin.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_texcoord;

uniform mat4 u_view_projection;

out vec3 v_position;
out vec3 v_normal;
out vec2 v_texcoord;

void main() {
  v_position = a_position;
  v_normal = a_normal;
  v_texcoord = a_texcoord;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
