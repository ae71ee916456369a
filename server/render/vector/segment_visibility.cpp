#include "render/vector/segment_visibility.h"

#include <algorithm>
#include <cmath>

#include "render/frame/draw_pacing.h"
#include "render/vector/parallel_runs.h"

namespace toond::render::vector {
namespace {

constexpr std::size_t kSegmentRun = 512;
// Hidden stretches this close on screen join: a segment passing under the
// shared side of two triangles that both hide it is not seen between them.
constexpr double kJoinPx = 0.02;

// Keeps the part of [lo, hi] where alpha + beta t >= 0.
void keep_where_positive(double alpha, double beta, double& lo, double& hi) {
  if (beta == 0) {
    if (alpha < 0) hi = lo;
    return;
  }
  const double root = -alpha / beta;
  if (beta > 0) {
    lo = std::max(lo, root);
  } else {
    hi = std::min(hi, root);
  }
}

// Whether the occluder borders the segment: its corners hold both ends.
bool borders(const Occluder& o, const Segment& s) {
  if (s.group_a == kNoGroup) return false;
  const auto holds = [&](std::uint32_t g) { return o.groups[0] == g || o.groups[1] == g || o.groups[2] == g; };
  return holds(s.group_a) && holds(s.group_b);
}

// The stretches of [lo, hi] in `hidden` (sorted, joined) and between them,
// appended to `out`.
void add_pieces(std::uint32_t segment, double lo, double hi, const std::vector<std::pair<double, double>>& hidden,
                bool hidden_pieces, std::vector<Piece>& out) {
  double at = lo;
  for (const auto& [h0, h1] : hidden) {
    if (h0 > at) out.push_back({segment, at, h0, false});
    if (hidden_pieces) out.push_back({segment, h0, h1, true});
    at = h1;
  }
  if (at < hi) out.push_back({segment, at, hi, false});
}

// The stretches of one segment, each hidden one the union of what its
// occluders hide, in `out`.
std::size_t split_segment(std::uint32_t index, const Segment& s, const ViewMesh& mesh, const OccluderGrid& grid,
                          const ScreenMap& screen, const VisibilityOptions& options, std::vector<std::uint32_t>& nearby,
                          GatherScratch& scratch, std::vector<Piece>& out) {
  const auto [lo, hi] = clip_to_view(s.a, s.b, screen, options.margin_px);
  if (!(lo < hi)) return 0;
  if (s.surely_hidden) {
    if (options.hidden_pieces) out.push_back({index, lo, hi, true});
    return 0;
  }
  const glm::dvec3 d = s.b - s.a;
  const glm::dvec3 a = s.a + lo * d;
  const glm::dvec3 b = s.a + hi * d;
  const glm::dvec2 p = screen.to_pixels(a);
  const glm::dvec2 q = screen.to_pixels(b);
  const glm::vec2 box_min = glm::vec2(glm::min(p, q));
  const glm::vec2 box_max = glm::vec2(glm::max(p, q));
  const float far_depth = static_cast<float>(std::max(-a.z, -b.z) + mesh.tolerance);
  grid.gather(p, q, nearby, scratch);
  std::vector<std::pair<double, double>> hidden;
  for (std::uint32_t i : nearby) {
    const Occluder& o = grid.occluder(i);
    if (o.near_depth > far_depth || glm::any(glm::lessThan(o.box_max, box_min)) ||
        glm::any(glm::greaterThan(o.box_min, box_max)) || borders(o, s)) {
      continue;
    }
    const auto h = hidden_interval(o, s.a, d, lo, hi, mesh.tolerance);
    if (h.first < h.second) hidden.push_back(h);
  }
  std::sort(hidden.begin(), hidden.end());
  const double join = kJoinPx * (hi - lo) / std::max(glm::length(q - p), 1e-12);
  std::vector<std::pair<double, double>> joined;
  for (const auto& h : hidden) {
    if (!joined.empty() && h.first <= joined.back().second + join) {
      joined.back().second = std::max(joined.back().second, h.second);
    } else {
      joined.push_back(h);
    }
  }
  // Nor does a stretch that short hide anything one could see: left, it
  // would only cut a line at a corner where a face touching it begins.
  std::erase_if(joined, [&](const auto& h) { return h.second - h.first < join; });
  add_pieces(index, lo, hi, joined, options.hidden_pieces, out);
  return nearby.size();
}

}  // namespace

std::pair<double, double> clip_to_view(const glm::dvec3& a, const glm::dvec3& b, const ScreenMap& screen,
                                       double margin_px) {
  const glm::dvec4 ca = screen.clip(a);
  const glm::dvec4 dc = screen.clip(b) - ca;
  const double mx = 1.0 + 2.0 * margin_px / screen.width;
  const double my = 1.0 + 2.0 * margin_px / screen.height;
  double lo = 0, hi = 1;
  // -w mx <= x <= w mx, the same for y, -w <= z <= w: each linear in t.
  keep_where_positive(ca.w * mx - ca.x, dc.w * mx - dc.x, lo, hi);
  keep_where_positive(ca.w * mx + ca.x, dc.w * mx + dc.x, lo, hi);
  keep_where_positive(ca.w * my - ca.y, dc.w * my - dc.y, lo, hi);
  keep_where_positive(ca.w * my + ca.y, dc.w * my + dc.y, lo, hi);
  keep_where_positive(ca.w + ca.z, dc.w + dc.z, lo, hi);
  keep_where_positive(ca.w - ca.z, dc.w - dc.z, lo, hi);
  return {lo, hi};
}

std::pair<double, double> hidden_interval(const Occluder& o, const glm::dvec3& a, const glm::dvec3& d, double lo,
                                          double hi, double tolerance) {
  // A side the occluder shares with another that hides widened by the
  // tolerance, its other sides and its plane narrowed: a point on a shared
  // side is hidden by both, however nearly the segment runs along it
  // (narrowed, a grazing segment would slip between them); a point on the
  // rim of what hides (a fold, a silhouette's fan of faces) or on the
  // occluder's own surface is hidden by neither.
  for (int k = 0; k < 4; ++k) {
    const glm::dvec3 n(o.planes[k]);
    const bool shared = k < 3 && (o.shared_sides >> k & 1u) != 0;
    const double slack = shared ? tolerance : -tolerance;
    keep_where_positive(glm::dot(n, a) + o.planes[k].w + slack, glm::dot(n, d), lo, hi);
    if (!(lo < hi)) break;
  }
  return {lo, hi};
}

Visibility split_by_visibility(const std::vector<Segment>& segments, const ViewMesh& mesh, const OccluderGrid& grid,
                               const ScreenMap& screen, const VisibilityOptions& options) {
  const std::size_t runs = (segments.size() + kSegmentRun - 1) / kSegmentRun;
  std::vector<std::vector<Piece>> pieces(runs);
  std::vector<std::size_t> tests(runs, 0);
  for_each_run(segments.size(), kSegmentRun, [&](std::size_t run, std::size_t first, std::size_t end) {
    if (std::chrono::steady_clock::now() > options.deadline) {
      throw RenderAborted("the line drawing passed its deadline");
    }
    std::vector<std::uint32_t> nearby;
    GatherScratch scratch;
    for (std::size_t i = first; i < end; ++i) {
      tests[run] += split_segment(static_cast<std::uint32_t>(i), segments[i], mesh, grid, screen, options, nearby,
                                  scratch, pieces[run]);
    }
  });
  Visibility visibility;
  for (std::size_t run = 0; run < runs; ++run) {
    visibility.pieces.insert(visibility.pieces.end(), pieces[run].begin(), pieces[run].end());
    visibility.occluder_tests += tests[run];
  }
  return visibility;
}

}  // namespace toond::render::vector
