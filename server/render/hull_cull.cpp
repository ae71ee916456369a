#include "render/hull_cull.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <tuple>

namespace toond::render {
namespace {

// How far a vertex the GPU draws may lie from where this file puts it: the
// rasterizer snaps to 1/256 px and the vertex stage rounds in float. Any
// triangle too thin for its winding to survive that is not trusted to
// cover anything.
constexpr double kVertexSlackPx = 1.0 / 64.0;
// Added round every box and every edge: far above that slack.
constexpr double kMarginPx = 0.5;
// The side of the cells an edge marks.
constexpr double kCellPx = 4.0;

using PositionBits = std::array<std::uint32_t, 3>;

PositionBits bits_of(const glm::vec3& p) {
  return {std::bit_cast<std::uint32_t>(p.x), std::bit_cast<std::uint32_t>(p.y), std::bit_cast<std::uint32_t>(p.z)};
}

// One id per distinct position (bit for bit: vertices split at a seam or a
// hard edge share theirs) for every used vertex; the rest keep their own.
std::vector<std::uint32_t> weld_by_position(std::span<const glm::vec3> positions, std::span<const std::uint32_t> used) {
  std::vector<std::uint32_t> weld(positions.size());
  for (std::uint32_t v = 0; v < weld.size(); ++v) weld[v] = v;
  std::vector<std::uint32_t> order(used.begin(), used.end());
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return bits_of(positions[a]) < bits_of(positions[b]); });
  for (std::size_t i = 1; i < order.size(); ++i) {
    if (bits_of(positions[order[i]]) == bits_of(positions[order[i - 1]])) weld[order[i]] = weld[order[i - 1]];
  }
  return weld;
}

struct HalfEdge {
  std::uint32_t low, high;  // welded ids, low < high
  std::uint32_t edge;       // 3 × triangle + corner
  bool forward;             // walked from low to high
};

// Pairs every edge walked once each way by two triangles; any other edge
// (open, shared by three or more, or walked the same way twice) keeps -1.
std::vector<std::int32_t> edge_neighbours(std::span<const std::uint32_t> indices, const std::vector<std::uint32_t>& weld) {
  std::vector<std::int32_t> neighbours(indices.size(), -1);
  std::vector<HalfEdge> edges;
  edges.reserve(indices.size());
  for (std::uint32_t e = 0; e < indices.size(); ++e) {
    const std::uint32_t corner = e % 3;
    const std::uint32_t a = weld[indices[e]];
    const std::uint32_t b = weld[indices[e - corner + (corner + 1) % 3]];
    if (a == b) continue;
    edges.push_back({std::min(a, b), std::max(a, b), e, a < b});
  }
  std::sort(edges.begin(), edges.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return std::tie(x.low, x.high) < std::tie(y.low, y.high);
  });
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t end = i + 1;
    while (end < edges.size() && edges[end].low == edges[i].low && edges[end].high == edges[i].high) ++end;
    const HalfEdge& x = edges[i];
    const HalfEdge& y = edges[i + 1 < edges.size() ? i + 1 : i];
    if (end - i == 2 && x.forward != y.forward && x.edge / 3 != y.edge / 3) {
      neighbours[x.edge] = static_cast<std::int32_t>(y.edge / 3);
      neighbours[y.edge] = static_cast<std::int32_t>(x.edge / 3);
    }
    i = end;
  }
  return neighbours;
}

// An axis-aligned box in window pixels.
struct Box {
  glm::dvec2 min{std::numeric_limits<double>::infinity()};
  glm::dvec2 max{-std::numeric_limits<double>::infinity()};
  void add(const glm::dvec2& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void add(const Box& b) {
    min = glm::min(min, b.min);
    max = glm::max(max, b.max);
  }
};

// A vertex where the main pass draws it and the box its hull corner may
// reach from there.
struct ProjectedVertex {
  glm::dvec2 window{0.0};
  Box reach;
};

// Cells over the viewport marking where the cover of the drawn faces may
// end, summed so a box's count costs four reads.
class EndGrid {
 public:
  EndGrid(int width, int height)
      : width_(width), height_(height),
        columns_(static_cast<int>(std::ceil(width / kCellPx))), rows_(static_cast<int>(std::ceil(height / kCellPx))),
        marks_(static_cast<std::size_t>(columns_ * rows_), 0) {}

  void mark(const glm::dvec2& a, const glm::dvec2& b) {
    const glm::dvec2 lo = glm::min(a, b) - kMarginPx;
    const glm::dvec2 hi = glm::max(a, b) + kMarginPx;
    if (hi.x < 0 || hi.y < 0 || lo.x > width_ || lo.y > height_) return;
    const int x0 = column(lo.x), x1 = column(hi.x), y0 = row(lo.y), y1 = row(hi.y);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) marks_[static_cast<std::size_t>(y * columns_ + x)] = 1;
  }

  void sum() {
    sums_.assign(static_cast<std::size_t>((columns_ + 1) * (rows_ + 1)), 0);
    for (int y = 0; y < rows_; ++y)
      for (int x = 0; x < columns_; ++x) {
        sums_[at(x + 1, y + 1)] = marks_[static_cast<std::size_t>(y * columns_ + x)] + sums_[at(x, y + 1)] +
                                  sums_[at(x + 1, y)] - sums_[at(x, y)];
      }
  }

  // Whether the box lies inside the viewport and meets no marked cell.
  bool clear(const Box& box) const {
    const glm::dvec2 lo = box.min - kMarginPx;
    const glm::dvec2 hi = box.max + kMarginPx;
    if (!(lo.x >= 0 && lo.y >= 0 && hi.x <= width_ && hi.y <= height_)) return false;
    const int x0 = column(lo.x), x1 = column(hi.x) + 1, y0 = row(lo.y), y1 = row(hi.y) + 1;
    return sums_[at(x1, y1)] - sums_[at(x0, y1)] - sums_[at(x1, y0)] + sums_[at(x0, y0)] == 0;
  }

 private:
  int column(double x) const { return std::clamp(static_cast<int>(std::floor(x / kCellPx)), 0, columns_ - 1); }
  int row(double y) const { return std::clamp(static_cast<int>(std::floor(y / kCellPx)), 0, rows_ - 1); }
  std::size_t at(int x, int y) const { return static_cast<std::size_t>(y * (columns_ + 1) + x); }

  double width_, height_;
  int columns_, rows_;
  std::vector<std::uint8_t> marks_;
  std::vector<std::int32_t> sums_;
};

// Clip → window pixels (y up, as GL rasterizes); nullopt outside the depth
// range or behind the eye, where the cut would end the cover.
std::optional<glm::dvec2> to_window(const glm::dvec4& clip, const HullCullView& view) {
  if (!(clip.w > 0.0) || !(std::abs(clip.z) <= clip.w) || !std::isfinite(clip.x) || !std::isfinite(clip.y)) {
    return std::nullopt;
  }
  return glm::dvec2((clip.x / clip.w + 1.0) * 0.5 * view.viewport_width,
                    (clip.y / clip.w + 1.0) * 0.5 * view.viewport_height);
}

// hull.vert in double: the corner moves along its offset by at most the
// full width (its obliquity factor only shortens the move, and the moved
// point stays on the segment, whose image is a segment).
std::optional<ProjectedVertex> project(const HullCullMesh& mesh, std::uint32_t v, const HullCullView& view) {
  const glm::dvec3 position = glm::dvec3(view.model * glm::dvec4(glm::dvec3(mesh.position(v)), 1.0));
  const glm::dvec4 clip = view.clip * glm::dvec4(position, 1.0);
  const std::optional<glm::dvec2> window = to_window(clip, view);
  if (!window) return std::nullopt;
  const glm::dvec3 raw(mesh.outline_offset(v));
  const glm::dvec3 turned = view.normal_matrix * raw;
  const double turned_len = glm::length(turned);
  const glm::dvec3 offset = turned_len > 0.0 ? turned * (glm::length(raw) / turned_len) : glm::dvec3(0.0);
  const double distance = view.width_px * view.world_per_px_at_w1 * std::abs(clip.w);
  const std::optional<glm::dvec2> moved = to_window(view.clip * glm::dvec4(position + offset * distance, 1.0), view);
  if (!moved) return std::nullopt;
  ProjectedVertex out{*window, {}};
  out.reach.add(*window);
  out.reach.add(*moved);
  return out;
}

// Twice the signed area, counter-clockwise positive, when its sign holds
// for any move of the corners within the slack; 0 where it may not.
double trusted_area2(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  const glm::dvec2 ab = b - a, ac = c - a;
  const double area2 = ab.x * ac.y - ab.y * ac.x;
  const double perimeter = glm::length(ab) + glm::length(ac) + glm::length(c - b);
  const double doubt = 2.0 * kVertexSlackPx * perimeter + 4.0 * kVertexSlackPx * kVertexSlackPx;
  return std::abs(area2) > doubt ? area2 : 0.0;
}

}  // namespace

HullCullMesh::HullCullMesh(std::span<const glm::vec3> positions, std::span<const glm::vec3> outline_offsets,
                           std::span<const std::uint32_t> indices, std::span<const scene::Submesh> submeshes)
    : positions_(positions), offsets_(outline_offsets), indices_(indices.begin(), indices.end()),
      submeshes_(submeshes.begin(), submeshes.end()) {
  used_ = indices_;
  std::sort(used_.begin(), used_.end());
  used_.erase(std::unique(used_.begin(), used_.end()), used_.end());
  neighbours_ = edge_neighbours(indices_, weld_by_position(positions_, used_));
}

std::optional<HullSubset> hull_faces_that_may_show(const HullCullMesh& mesh, const HullCullView& view) {
  if (view.viewport_width <= 0 || view.viewport_height <= 0) return std::nullopt;
  std::vector<ProjectedVertex> vertices(mesh.used_vertices().empty() ? 0 : mesh.used_vertices().back() + 1);
  for (std::uint32_t v : mesh.used_vertices()) {
    const std::optional<ProjectedVertex> projected = project(mesh, v, view);
    if (!projected) return std::nullopt;
    vertices[v] = *projected;
  }
  const std::span<const std::uint32_t> indices = mesh.indices();
  const std::size_t triangles = indices.size() / 3;
  // The faces the main pass draws, with a winding no rounding can flip.
  const double drawn_sign = view.drawn_clockwise ? -1.0 : 1.0;
  std::vector<std::uint8_t> drawn(triangles);
  for (std::size_t t = 0; t < triangles; ++t) {
    const double area2 = trusted_area2(vertices[indices[3 * t]].window, vertices[indices[3 * t + 1]].window,
                                       vertices[indices[3 * t + 2]].window);
    drawn[t] = area2 * drawn_sign > 0.0;
  }
  EndGrid ends(view.viewport_width, view.viewport_height);
  for (std::size_t t = 0; t < triangles; ++t) {
    if (!drawn[t]) continue;
    for (int k = 0; k < 3; ++k) {
      const std::int32_t other = mesh.neighbour(t, k);
      if (other >= 0 && drawn[static_cast<std::size_t>(other)]) continue;
      ends.mark(vertices[indices[3 * t + static_cast<std::size_t>(k)]].window,
                vertices[indices[3 * t + static_cast<std::size_t>((k + 1) % 3)]].window);
    }
  }
  ends.sum();
  HullSubset out;
  out.indices.reserve(indices.size());
  for (const scene::Submesh& sub : mesh.submeshes()) {
    scene::Submesh kept{static_cast<std::uint32_t>(out.indices.size()), 0, sub.material};
    for (std::size_t e = sub.first_index; e < sub.first_index + sub.index_count; e += 3) {
      const std::size_t t = e / 3;
      if (drawn[t]) {
        Box box;
        for (std::size_t c = 0; c < 3; ++c) box.add(vertices[indices[e + c]].reach);
        if (ends.clear(box)) {
          ++out.culled_triangles;
          continue;
        }
      }
      out.indices.insert(out.indices.end(), &indices[e], &indices[e] + 3);
    }
    kept.index_count = static_cast<std::uint32_t>(out.indices.size()) - kept.first_index;
    out.submeshes.push_back(kept);
  }
  return out;
}

}  // namespace toond::render
