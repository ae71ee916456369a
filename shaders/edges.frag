#version 430 core
// Screen-space edge outline over the prepass's normals and depths. An edge
// lies between two neighbouring pixels when one is background and the other
// not (silhouettes), when depth jumps between them (intersections, parts in
// front of parts) or when the normal turns by more than the crease angle
// (hard edges). Each pixel looks for the nearest edge along the four axes,
// as far as an edge that could still touch it lies, and is covered by the line as far as a
// line of the full width centred on that edge covers it: widths are exact
// to a fraction of a pixel, not rounded to whole pixels. The depth threshold
// is a fraction of the model's size, so the test does not depend on how
// large the model is.
uniform sampler2D u_normal_depth;  // xyz normal, w distance from the eye; w = 0: background
uniform float u_half_width;        // pixels: half the line width
uniform float u_depth_threshold;   // scene units
uniform float u_cos_crease;
uniform vec3 u_edge_color;         // linear

layout(location = 0) out vec4 o_color;

ivec2 g_size;

bool is_background(vec4 s) { return s.w <= 0.0; }

vec4 sample_at(ivec2 p) { return texelFetch(u_normal_depth, clamp(p, ivec2(0), g_size - 1), 0); }

// Whether an edge lies between neighbours a and b; `before` is the pixel on
// a's other side. A depth jump shows as a change of the depth's slope (a
// plane seen at a grazing angle changes depth fast, but evenly, and must not
// count). With CREASES_ONLY another pass draws the silhouette: only turns of
// the normal between two surface pixels count.
bool edge_between(vec4 before, vec4 a, vec4 b) {
#ifdef CREASES_ONLY
  if (is_background(a) || is_background(b)) return false;
#else
  if (is_background(a) != is_background(b)) return true;
  if (is_background(a)) return false;
  if (!is_background(before) && abs((b.w - a.w) - (a.w - before.w)) > u_depth_threshold) return true;
#endif
  return dot(a.xyz, b.xyz) < u_cos_crease;
}

// Distance in pixels from this pixel's centre to the nearest edge along
// `step`, which lies halfway between two pixels; a large number when there
// is none within `reach` pixels.
float edge_distance_along(ivec2 p, ivec2 step, int reach) {
  vec4 before = sample_at(p - step);
  vec4 a = sample_at(p);
  for (int k = 1; k <= reach; ++k) {
    vec4 b = sample_at(p + k * step);
    if (edge_between(before, a, b)) return float(k) - 0.5;
    before = a;
    a = b;
  }
  return 1e6;
}

void main() {
  g_size = textureSize(u_normal_depth, 0);
  ivec2 p = ivec2(gl_FragCoord.xy);
  // An edge at 45° crosses the axes √2 times farther away than it lies.
  int reach = int(ceil((u_half_width + 0.5) * 1.4143));
  float dx = min(edge_distance_along(p, ivec2(1, 0), reach), edge_distance_along(p, ivec2(-1, 0), reach));
  float dy = min(edge_distance_along(p, ivec2(0, 1), reach), edge_distance_along(p, ivec2(0, -1), reach));
  // A straight edge crossing both axes at dx and dy lies dx·dy/√(dx²+dy²)
  // from the pixel; crossing one axis only, it runs along the other.
  float d = min(dx, dy);
  if (dx < 1e5 && dy < 1e5) d = dx * dy / sqrt(dx * dx + dy * dy);
  float coverage = clamp(u_half_width - d + 0.5, 0.0, 1.0);
  if (coverage <= 0.0) discard;
  o_color = vec4(u_edge_color, coverage);
}
