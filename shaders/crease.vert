#version 430 core
// Crease lines: the corners of each crease edge's two faces (an edge and
// the third corner of each face, GL_LINES_ADJACENCY) to clip space, posed
// and placed exactly as the main pass places them (toon.vert), so the
// geometry stage's face planes are the ones whose depths the main pass
// left. The points of seams where parts cross (u_seams) come posed
// already (render/frame/gpu_seams.h): only placed.
#include "attributes.glsl"
#include "view.glsl"
#include "object.glsl"
#include "skinning.glsl"

// Nonzero: the primitives are seams where parts cross (crease.geom).
uniform int u_seams;

void main() {
  vec3 position = u_seams != 0 ? a_position : posed_vertex().position;
  vec4 world = u_model * vec4(position, 1.0);
  gl_Position = u_view_projection * world;
}
