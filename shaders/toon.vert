#version 430 core
// Main pass vertex stage. Positions arrive relative to the model's origin
// (recentred in double precision on the CPU); u_model places them in the
// scene, relative to the scene's middle (composed in double on the CPU), so
// the float maths here stays precise however far the model sits from its
// own coordinate origin. Lighting happens in that scene-relative space.
#include "attributes.glsl"
#include "view.glsl"
#include "object.glsl"
#include "skinning.glsl"

out vec3 v_position;
out vec3 v_normal;
out vec2 v_texcoord;
out vec4 v_tangent;
out vec3 v_color;

void main() {
  PosedVertex posed = posed_vertex();
  vec4 world = u_model * vec4(posed.position, 1.0);
  v_position = world.xyz;
  v_normal = u_normal_matrix * posed.normal;
  v_texcoord = a_texcoord;
  // Tangents lie in the surface: they follow the model matrix itself.
  v_tangent = vec4(mat3(u_model) * posed.tangent.xyz, posed.tangent.w);
  v_color = a_color;
  gl_Position = u_view_projection * world;
}
