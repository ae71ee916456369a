#version 430 core
// Crease lines: the corners of each crease edge's two faces (an edge and
// the third corner of each face, GL_LINES_ADJACENCY) to clip space, posed
// and placed exactly as the main pass places them (toon.vert), so the
// geometry stage's face planes are the ones whose depths the main pass
// left.
#include "attributes.glsl"
#include "view.glsl"
#include "object.glsl"
#include "skinning.glsl"

void main() {
  PosedVertex posed = posed_vertex();
  vec4 world = u_model * vec4(posed.position, 1.0);
  gl_Position = u_view_projection * world;
}
