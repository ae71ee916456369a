#version 430 core
// Screen-space edge outline over the prepass's normals and depths. An edge
// lies between two neighbouring pixels when one is background and the other
// not (silhouettes), when depth jumps between them (intersections, parts in
// front of parts) or when the normal turns by more than the crease angle
// (hard edges). Each pixel looks for the nearest edge along the four axes,
// as far as an edge that could still touch it lies, and is covered by the
// line as far as a line of the full width centred on that edge covers it:
// widths are exact to a fraction of a pixel, not rounded to whole pixels.
// For silhouettes the prepass is multisampled: the share of a pixel the
// model covers moves a silhouette from the border between two pixels to
// where it crosses them. CREASES_ONLY (another pass draws the silhouette)
// leaves the silhouette's work out. The depth threshold is a fraction of
// the model's size, so the test does not depend on how large the model is.
// With u_readable_area_px (pixel-art sprites) a line between two surface
// pixels is drawn only where the areas on both sides run on that far along
// the axis walked: a part narrower than that would be all line. With
// u_whole_pixels (pixel art again) a line is whole pixels, not shares: the
// one pixel after each edge along x and along y, fully covered (a line
// centred on the border between two pixels would cover half of each, a grey
// that the palette then snaps to a stray colour).
layout(binding = 0) uniform sampler2D u_normal_depth;  // xyz normal, w distance from the eye; w = 0: background
layout(binding = 1) uniform sampler2D u_coverage;  // the share of each pixel the model covers
#include "outline_style.glsl"

layout(location = 0) out vec4 o_color;

float half_width() { return 0.5 * u_width; }  // pixels
bool whole_pixels() { return u_whole_pixels != 0; }

ivec2 g_size;
const float kNone = 1e6;  // no edge within reach

vec4 texel_at(ivec2 p) { return texelFetch(u_normal_depth, clamp(p, ivec2(0), g_size - 1), 0); }

float coverage_at(ivec2 p) { return texelFetch(u_coverage, clamp(p, ivec2(0), g_size - 1), 0).r; }

bool is_background(vec4 t) { return t.w <= 0.0; }

// Whether an edge lies between neighbours a and b; `before` is the pixel on
// a's other side. A depth jump shows as a change of the depth's slope (a
// plane seen at a grazing angle changes depth fast, but evenly, and must not
// count). With CREASES_ONLY only turns of the normal between two surface
// pixels count.
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

// Whether the area of `first` (at `at`) runs on for u_readable_area_px
// pixels along `step` without meeting the background or another turn.
bool area_runs_on(ivec2 at, ivec2 step, vec4 first) {
  for (int k = 1; k < u_readable_area_px; ++k) {
    vec4 t = texel_at(at + k * step);
    if (is_background(t) || dot(t.xyz, first.xyz) < u_cos_crease) return false;
  }
  return true;
}

// Whether the edge between a (at `at`) and b, its neighbour along `step`,
// is one to draw: silhouettes always, lines between two surface pixels
// only between areas wide enough to read.
bool readable(ivec2 at, ivec2 step, vec4 a, vec4 b) {
  if (u_readable_area_px <= 1 || is_background(a) || is_background(b)) return true;
  return area_runs_on(at, -step, a) && area_runs_on(at + step, step, b);
}

#ifndef CREASES_ONLY
// How far from the border between a (at `at`) and b a silhouette crosses
// the row `before`, a, b, `after`, along `step`: each uncovered share of
// the model's pixels moves it back, each covered share of the background
// pixels forward. A straight edge crossing the row within those four
// pixels is placed to the precision of the sample count; one running
// nearly along the row crosses it far away, and the other axis decides.
float silhouette_shift(ivec2 at, ivec2 step, vec4 before, vec4 a, vec4 b) {
  bool model_first = is_background(b);
  vec4 after = texel_at(at + 2 * step);
  float shift = coverage_at(at) + coverage_at(at + step) - 1.0;
  float before_share = coverage_at(at - step);
  float after_share = coverage_at(at + 2 * step);
  if (model_first) {
    if (!is_background(before)) shift += before_share - 1.0;
    if (is_background(after)) shift += after_share;
  } else {
    if (is_background(before)) shift += before_share;
    if (!is_background(after)) shift += after_share - 1.0;
  }
  return model_first ? shift : -shift;
}
#endif

// Distance in pixels from this pixel's centre to the nearest edge along
// `step`; kNone when there is none within `reach` pixels.
float edge_distance_along(ivec2 p, ivec2 step, int reach) {
  vec4 before = texel_at(p - step);
  vec4 a = texel_at(p);
  vec4 b = a;
  int found = 0;
  for (int k = 1; k <= reach; ++k) {
    b = texel_at(p + k * step);
    if (edge_between(before, a, b) && readable(p + (k - 1) * step, step, a, b)) {
      found = k;
      break;
    }
    before = a;
    a = b;
  }
  if (found == 0) return kNone;
  float border = float(found) - 0.5;
#ifndef CREASES_ONLY
  if (is_background(a) != is_background(b)) {
    return max(border + silhouette_shift(p + (found - 1) * step, step, before, a, b), 0.0);
  }
#endif
  return border;
}

// The nearest edge along one axis (`along`), in either direction; `toward`
// is the direction it lies in.
float nearest_along(ivec2 p, ivec2 along, int reach, out ivec2 toward) {
  if (whole_pixels()) {
    toward = -along;
    return edge_distance_along(p, -along, reach);
  }
  float ahead = edge_distance_along(p, along, reach);
  float behind = edge_distance_along(p, -along, reach);
  toward = ahead <= behind ? along : -along;
  return min(ahead, behind);
}

// Distance to an edge that crosses only one axis within reach, `d` away
// along `toward`: the crossings seen from the two neighbours across that
// axis give the edge's slope, which brings it nearer by 1/√(1 + slope²).
// An edge 20° off the other axis would otherwise lie 6 % too far. Crease
// lines, placed on whole pixels, are spared the two extra walks.
float distance_by_slope(ivec2 p, ivec2 toward, float d, int reach) {
#ifdef CREASES_ONLY
  return d;
#else
  ivec2 across = ivec2(toward.y, toward.x);
  float next = edge_distance_along(p + across, toward, reach + 1);
  float previous = edge_distance_along(p - across, toward, reach + 1);
  if (next >= kNone || previous >= kNone) return d;
  float slope = 0.5 * (next - previous);
  return d / sqrt(1.0 + slope * slope);
#endif
}

void main() {
  g_size = textureSize(u_normal_depth, 0);
  ivec2 p = ivec2(gl_FragCoord.xy);
  // An edge at 45° crosses the axes √2 times farther away than it lies.
  int reach = int(ceil((half_width() + 0.5) * 1.4143));
  ivec2 toward_x, toward_y;
  float dx = nearest_along(p, ivec2(1, 0), reach, toward_x);
  float dy = nearest_along(p, ivec2(0, 1), reach, toward_y);
  // A straight edge crossing both axes at dx and dy lies dx·dy/√(dx²+dy²)
  // from the pixel.
  float d = min(dx, dy);
  if (dx < kNone && dy < kNone) d = dx * dy / max(sqrt(dx * dx + dy * dy), 1e-6);
  else if (dx < kNone && !whole_pixels()) d = distance_by_slope(p, toward_x, dx, reach);
  else if (dy < kNone && !whole_pixels()) d = distance_by_slope(p, toward_y, dy, reach);
  float coverage = whole_pixels() ? float(d <= half_width()) : clamp(half_width() - d + 0.5, 0.0, 1.0);
  if (coverage <= 0.0) discard;
  o_color = vec4(u_outline_color, coverage);
}
