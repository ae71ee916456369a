#version 430 core
// Crease lines along the model's crease edges (scene/mesh/crease_edges.h): each
// edge becomes one primitive of the outline's width centred on it, reaching
// half a width past its ends so lines meeting at a corner join (the fragment
// stage keeps only what lies within half the width of the segment itself:
// round caps and joins), plus a margin for the line's antialiased border.
// With WIDE_LINES it is a GL line as wide as the pass sets (glLineWidth),
// else a quad of two triangles: a CPU rasterizer pays for a long thin
// primitive by the blocks it crosses, and the two halves of a quad cross
// each block twice. The depth a line is tested at is worked out by the
// fragment stage (crease.frag) from the plane of the face on each side of
// the edge, so the depth test against what the main pass left keeps the
// line where its faces show and hides it where something nearer covers
// them; a line carries both faces' planes for it. A crease shows only
// where both its faces do: the fragment stage also checks the face across
// the edge. Input: c1, a, b, c2 (face 1 is (a, b, c1) in its winding). An
// edge whose faces fold over one another on screen draws nothing: it is a
// silhouette, which the hull or wireframe draws, or it lies behind its own
// faces.
// A seam where two parts cross (u_seams, scene/mesh/intersection_lines.h) comes
// as p1, a, b, p2, a point of each face's plane off the segment; both
// planes go on past the segment to either side. The half of each that
// shows is the nearer on its side of the line on screen: the eye looks
// into the empty wedge between the two surfaces, and whatever lies nearer
// on a side is what bounds it there. So face 1's half lies on the side
// where its plane's depth grows the slower, face 2's on the other. Both
// walls of the wedge face the eye that looks into it: where either turns
// to the side the main pass culls (a face lying nearly in the other's
// plane, seen from its back), no seam shows. (a, b, p1) winds as face 1,
// (a, b, p2) as face 2.
layout(lines_adjacency) in;
#ifdef WIDE_LINES
layout(line_strip, max_vertices = 2) out;
#else
layout(triangle_strip, max_vertices = 4) out;
#endif

flat out vec2 v_segment_a;  // the edge's ends in window coordinates
flat out vec2 v_segment_b;
flat out float v_depth_a;   // NDC depth at a
// The faces' planes: how NDC depth changes per window pixel on face 1's
// side (xy) and on face 2's (zw).
flat out vec4 v_depth_gradients;
flat out vec2 v_toward_face1;  // unit, across the edge toward face 1's side

#include "view.glsl"

// The side of its faces the main pass culled for this object, by winding
// on screen: 0 none, 1 clockwise (GL's back faces), 2 counter-clockwise.
// A crease whose faces both turn that way is hidden by the model itself.
uniform int u_culled_winding;
// Nonzero: the primitives are seams where parts cross, not crease edges.
uniform int u_seams;

// How far the line's primitive reaches to each side of the edge, in pixels:
// half the outline's width and a margin (render/passes/crease_pass.cpp's
// line_reach, which also sizes the GL line).
uniform float u_line_reach;
#ifdef WIDE_LINES
// How far past the line's ends, in its reach, the GL line must go to hold
// its round caps: a line drawn without multisampling ends across its major
// axis (x or y), which at 45° lies 1/√2 of the way out.
const float kEndReach = 1.41421356;
#else
const float kEndReach = 1.0;
#endif

#include "scene_depth.glsl"

vec2 to_window(vec4 clip) { return (clip.xy / clip.w * 0.5 + 0.5) * u_viewport_px; }

float cross2(vec2 u, vec2 v) { return u.x * v.y - u.y * v.x; }

// How NDC depth changes per window pixel in the plane of the face a, b, c
// (over the window a plane's NDC depth is affine, even in perspective).
// A face seen nearly edge-on has no plane to speak of: the line keeps the
// edge's own depth across it.
vec2 depth_gradient(vec2 a, float za, vec2 b, float zb, vec2 c, float zc) {
  vec2 e = b - a;
  vec2 f = c - a;
  float det = cross2(e, f);
  if (abs(det) <= 1e-3 * length(e) * length(f)) return e * (zb - za) / max(dot(e, e), 1e-12);
  return vec2((zb - za) * f.y - (zc - za) * e.y, (zc - za) * e.x - (zb - za) * f.x) / det;
}

// Whether the edge shows at some point along it, the middles of stretches
// of 8 pixels (up to 16): where its depth is no farther than what was drawn there,
// give or take its faces' depth change over a pixel and a half and a few
// of the depth buffer's steps. Hidden edges (on the far side of an open
// model, behind other parts) are then not rasterised at all: a long thin
// quad costs a tiled rasteriser by the tiles it crosses, whether its
// fragments pass or not. A point between those that shows alone is lost
// with its edge. The ends are not asked: an edge hidden behind the model's
// own faces but for its end on the silhouette would draw its round cap
// out past it.
bool edge_shows(vec2 a, float za, vec2 b, float zb, float slope) {
  int steps = int(clamp(ceil(distance(a, b) / 8.0), 1.0, 16.0));
  float slack = 1.5 * 0.5 * slope + 8.0 / 16777216.0;
  for (int i = 0; i < steps; ++i) {
    float t = (float(i) + 0.5) / float(steps);
    float drawn = scene_depth(mix(a, b, t), 0);
    if (0.5 * mix(za, zb, t) + 0.5 <= drawn + slack) return true;
  }
  return false;
}

vec2 g_a;
vec2 g_b;
float g_depth_a;
vec4 g_gradients;
vec2 g_toward_face1;

void emit(vec2 window, float depth) {
  gl_Position = vec4(window / u_viewport_px * 2.0 - 1.0, depth, 1.0);
  // Set before every vertex: outputs are undefined after EmitVertex.
  v_segment_a = g_a;
  v_segment_b = g_b;
  v_depth_a = g_depth_a;
  v_depth_gradients = g_gradients;
  v_toward_face1 = g_toward_face1;
  EmitVertex();
}

void main() {
  for (int i = 0; i < 4; ++i) {
    // Corners behind the eye plane would project inside out.
    if (gl_in[i].gl_Position.w <= 0.0) return;
  }
  vec4 c1 = gl_in[0].gl_Position;
  vec4 a = gl_in[1].gl_Position;
  vec4 b = gl_in[2].gl_Position;
  vec4 c2 = gl_in[3].gl_Position;
  g_a = to_window(a);
  g_b = to_window(b);
  vec2 s1 = to_window(c1);
  vec2 s2 = to_window(c2);
  vec2 e = g_b - g_a;
  float len = length(e);
  if (len < 1e-6) return;
  vec2 along = e / len;
  vec2 left = vec2(-along.y, along.x);
  float za = a.z / a.w;
  float zb = b.z / b.w;
  vec2 grad1 = depth_gradient(g_a, za, g_b, zb, s1, c1.z / c1.w);
  vec2 grad2 = depth_gradient(g_a, za, g_b, zb, s2, c2.z / c2.w);
  // Whether face 1's half of the line lies left of a→b on screen.
  bool face1_left;
  if (u_seams != 0) {
    float side1 = cross2(e, s1 - g_a);
    float side2 = cross2(e, s2 - g_a);
    if (u_culled_winding == 1 && (side1 < 0.0 || side2 < 0.0)) return;
    if (u_culled_winding == 2 && (side1 > 0.0 || side2 > 0.0)) return;
    face1_left = dot(grad1, left) <= dot(grad2, left);
  } else {
    float side1 = cross2(e, s1 - g_a);
    float side2 = cross2(e, s2 - g_a);
    if (side1 * side2 >= 0.0) return;  // folded over: a silhouette, or behind its faces
    // Both faces wind as face 1 does, unfolded: counter-clockwise when c1
    // lies left of a→b.
    if (u_culled_winding == 1 && side1 < 0.0) return;
    if (u_culled_winding == 2 && side1 > 0.0) return;
    face1_left = side1 > 0.0;
  }

  float slope = max(abs(grad1.x) + abs(grad1.y), abs(grad2.x) + abs(grad2.y));
  if (!edge_shows(g_a, za, g_b, zb, slope)) return;
  float reach = u_line_reach;
  g_toward_face1 = face1_left ? left : -left;
  g_depth_a = za;
  g_gradients = vec4(grad1, grad2);
  vec2 past = along * reach * kEndReach;
  float z_past = reach * kEndReach * (zb - za) / len;
#ifdef WIDE_LINES
  emit(g_a - past, za - z_past);
  emit(g_b + past, zb + z_past);
#else
  vec2 side = left * reach;
  emit(g_a - past + side, za - z_past);
  emit(g_b + past + side, zb + z_past);
  emit(g_a - past - side, za - z_past);
  emit(g_b + past - side, zb + z_past);
#endif
  EndPrimitive();
}
