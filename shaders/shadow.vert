#version 430 core
// Shadow pass: depth as the shadow-casting light sees the model.
#include "attributes.glsl"
#include "object.glsl"
#include "skinning.glsl"

uniform mat4 u_light_view_projection;

out vec2 v_texcoord;  // for the alpha test of masked materials

void main() {
  v_texcoord = a_texcoord;
  gl_Position = u_light_view_projection * (u_model * vec4(posed_vertex().position, 1.0));
}
