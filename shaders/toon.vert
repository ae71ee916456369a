#version 430 core
// Main pass vertex stage. Positions arrive relative to the model's origin
// (recentred in double precision on the CPU), so the float maths here stays
// precise however far the model sits from its own coordinate origin.
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec2 a_texcoord;
layout(location = 4) in vec4 a_tangent;  // xyz, w = bitangent handedness
layout(location = 5) in vec3 a_color;    // sRGB-encoded vertex colour

uniform mat4 u_view_projection;

out vec3 v_position;
out vec3 v_normal;
out vec2 v_texcoord;
out vec4 v_tangent;
out vec3 v_color;

void main() {
  v_position = a_position;
  v_normal = a_normal;
  v_texcoord = a_texcoord;
  v_tangent = a_tangent;
  v_color = a_color;
  gl_Position = u_view_projection * vec4(a_position, 1.0);
}
