#version 430 core
// Back-face wireframe lines of a chosen pixel width. Core profile has no wide
// lines, so each edge of a back-facing triangle becomes a quad `line_px()`
// pixels across. Front faces drawn in the main pass hide the lines except
// where back faces show past them: at the silhouette and at folds, which is
// what makes it an outline. Culling happens here, before the quads exist,
// since GL would cull the emitted quads, not the source triangle.
layout(triangles) in;
layout(triangle_strip, max_vertices = 12) out;

in vec2 g_texcoord[];
in float g_facing[];
out vec2 v_texcoord;
flat out vec2 v_segment_a;  // the edge's ends in window coordinates
flat out vec2 v_segment_b;

#include "view.glsl"
#include "outline_style.glsl"

// Half of each line lies inside the silhouette, under the front faces:
// lines twice as wide leave the outline's width showing.
float line_px() { return 2.0 * u_width; }

vec2 to_screen(vec4 clip) { return (clip.xy / clip.w * 0.5 + 0.5) * u_viewport_px; }

void emit_edge(int a, int b) {
  vec4 ca = gl_in[a].gl_Position;
  vec4 cb = gl_in[b].gl_Position;
  vec2 sa = to_screen(ca);
  vec2 sb = to_screen(cb);
  vec2 along = sb - sa;
  float len = length(along);
  if (len < 1e-6) return;
  along /= len;
  // Half the width to each side, and half a width past each end so that
  // neighbouring edges join without notches, plus a pixel: the fragment
  // shader gives the line's edge its coverage, which reaches half a pixel
  // (diagonally √½) past the width. A quad cut at the width would also cut
  // the samples of those pixels and thin the line by up to half a pixel.
  const float kCoverageMargin = 1.0;
  vec2 side = vec2(-along.y, along.x) * (0.5 * line_px() + kCoverageMargin);
  vec2 ext = along * (0.5 * line_px() + kCoverageMargin);
  vec2 to_ndc = 2.0 / u_viewport_px;
  // Set before every vertex: flat outputs are undefined after EmitVertex.
  gl_Position = vec4(ca.xy + (-side - ext) * to_ndc * ca.w, ca.zw);
  v_texcoord = g_texcoord[a];
  v_segment_a = sa;
  v_segment_b = sb;
  EmitVertex();
  gl_Position = vec4(ca.xy + (side - ext) * to_ndc * ca.w, ca.zw);
  v_texcoord = g_texcoord[a];
  v_segment_a = sa;
  v_segment_b = sb;
  EmitVertex();
  gl_Position = vec4(cb.xy + (-side + ext) * to_ndc * cb.w, cb.zw);
  v_texcoord = g_texcoord[b];
  v_segment_a = sa;
  v_segment_b = sb;
  EmitVertex();
  gl_Position = vec4(cb.xy + (side + ext) * to_ndc * cb.w, cb.zw);
  v_texcoord = g_texcoord[b];
  v_segment_a = sa;
  v_segment_b = sb;
  EmitVertex();
  EndPrimitive();
}

void main() {
  // Triangles crossing the eye plane would project inside out; skip them.
  if (gl_in[0].gl_Position.w <= 0.0 || gl_in[1].gl_Position.w <= 0.0 || gl_in[2].gl_Position.w <= 0.0) return;
  vec2 p0 = to_screen(gl_in[0].gl_Position);
  vec2 p1 = to_screen(gl_in[1].gl_Position);
  vec2 p2 = to_screen(gl_in[2].gl_Position);
  float area = (p1.x - p0.x) * (p2.y - p0.y) - (p2.x - p0.x) * (p1.y - p0.y);
  if (area > 0.0) return;  // counter-clockwise on screen: a front face
  // Wound as a back face but its corners' normals face the viewer: a
  // triangle folded over in the middle of the front (a simplified level
  // of detail can fold one near a pole), not a face turned away.
  if (g_facing[0] + g_facing[1] + g_facing[2] > 0.0) return;
  emit_edge(0, 1);
  emit_edge(1, 2);
  emit_edge(2, 0);
}
