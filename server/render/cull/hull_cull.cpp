#include "render/cull/hull_cull.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

#include "render/cull/cover_layers.h"

namespace toond::render {
namespace {

// How far a vertex the GPU draws may lie from where this file puts it: the
// rasterizer snaps to 1/256 px and the vertex stage rounds in float. Any
// triangle too thin for its winding to survive that is not trusted to
// cover anything.
constexpr double kVertexSlackPx = 1.0 / 64.0;
// Added round every box and every edge: far above that slack.
constexpr double kMarginPx = 0.5;
// The side of the cells that mark where the cover ends and where it is:
// about a face's size, a power of two in [2, 16] px. Finer cells leave out
// more faces near the silhouette; past a face's size they only cost (a
// grid of 2 px cells over 1024² took spot's cull from 0.5 to 4 ms).
double cell_px(const HullCullView& view, std::size_t triangles) {
  const double px_per_face = static_cast<double>(view.viewport_width) * view.viewport_height /
                             static_cast<double>(std::max<std::size_t>(triangles, 1));
  double cell = 2.0;
  while (cell < 16.0 && 2.0 * cell <= std::sqrt(px_per_face)) cell *= 2.0;
  return cell;
}

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
std::vector<std::int32_t> edge_neighbours(std::span<const std::uint32_t> indices,
                                          const std::vector<std::uint32_t>& weld) {
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
  std::sort(edges.begin(), edges.end(),
            [](const HalfEdge& x, const HalfEdge& y) { return std::tie(x.low, x.high) < std::tie(y.low, y.high); });
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

// Which way a face turns where the main pass draws it.
enum FaceTurn : std::uint8_t {
  kTurnedAway = 0,  // surely: culled, or its winding the skipped one
  kDrawn = 1,       // surely drawn, its winding the drawn one
  kUnsure = 2,      // too thin for its winding to survive rounding
};

// An axis-aligned box in window pixels.
struct Box {
  glm::vec2 min{0.0f};
  glm::vec2 max{0.0f};
};

// A vertex where the main pass draws it (window pixels, y up), the ends
// of the stretch its hull corner lies on (half and the whole of its move)
// and the box that corner may reach from the vertex (in float: its
// rounding is far below the margin and the slack).
struct ProjectedVertex {
  glm::dvec2 window{0.0};
  glm::vec2 half_move{0.0f};
  glm::vec2 whole_move{0.0f};
  glm::vec2 reach_min{0.0f};
  glm::vec2 reach_max{0.0f};
};

// Cells of a grid: columns [x0, x1), rows [y0, y1).
struct CellRect {
  int x0, x1, y0, y1;
};

// Counts per cell of a grid over the viewport, summed so a box's count
// costs four reads.
class CellCounts {
 public:
  // Every cell uncounted, over a viewport of this size.
  void reset(int width, int height, double cell) {
    width_ = width;
    height_ = height;
    per_px_ = 1.0 / cell;
    per_px_f_ = static_cast<float>(per_px_);
    columns_ = static_cast<int>(std::ceil(width * per_px_));
    rows_ = static_cast<int>(std::ceil(height * per_px_));
    counts_.assign(static_cast<std::size_t>(columns_ * rows_), 0);
  }

  // Counts every cell the box (grown by the margin) overlaps.
  void add_box(const glm::dvec2& a, const glm::dvec2& b) {
    const glm::dvec2 lo = glm::min(a, b) - kMarginPx;
    const glm::dvec2 hi = glm::max(a, b) + kMarginPx;
    if (hi.x < 0 || hi.y < 0 || lo.x > width_ || lo.y > height_) return;
    const int x0 = column(lo.x), x1 = column(hi.x), y0 = row(lo.y), y1 = row(hi.y);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) counts_[static_cast<std::size_t>(y * columns_ + x)] = 1;
  }
  // Counts the cell holding the point.
  void add_point(const glm::dvec2& p) {
    if (p.x < 0 || p.y < 0 || p.x >= width_ || p.y >= height_) return;
    counts_[static_cast<std::size_t>(row(p.y) * columns_ + column(p.x))] = 1;
  }

  // Each entry: the counted cells above and left of it (a running sum
  // along its row added to the entry above, so rows do not wait on each
  // other's last sums).
  void sum() {
    sums_.assign(static_cast<std::size_t>((columns_ + 1) * (rows_ + 1)), 0);
    for (int y = 0; y < rows_; ++y) {
      const std::uint8_t* counts = &counts_[static_cast<std::size_t>(y * columns_)];
      const std::int32_t* above = &sums_[at(1, y)];
      std::int32_t* row = &sums_[at(1, y + 1)];
      std::int32_t along = 0;
      for (int x = 0; x < columns_; ++x) {
        along += counts[x];
        row[x] = above[x] + along;
      }
    }
  }

  // The cells a box the viewport holds overlaps (its corners are not
  // negative, so truncating floors).
  CellRect overlapped_by(const Box& box) const {
    return {static_cast<int>(box.min.x * per_px_f_),
            std::min(static_cast<int>(box.max.x * per_px_f_), columns_ - 1) + 1,
            static_cast<int>(box.min.y * per_px_f_), std::min(static_cast<int>(box.max.y * per_px_f_), rows_ - 1) + 1};
  }
  // Whether one of these cells was counted.
  bool any(const CellRect& cells) const { return count(cells.x0, cells.x1, cells.y0, cells.y1) > 0; }
  // Whether a cell wholly inside the box was counted.
  // Only for a box the viewport holds (its corners are not negative, so
  // truncating floors).
  bool any_inside(const Box& box) const {
    const auto up = [](double v) {
      const int i = static_cast<int>(v);
      return i + (i < v ? 1 : 0);
    };
    const int x0 = up(box.min.x * per_px_), x1 = static_cast<int>(box.max.x * per_px_);
    const int y0 = up(box.min.y * per_px_), y1 = static_cast<int>(box.max.y * per_px_);
    return count(x0, std::min(x1, columns_), y0, std::min(y1, rows_)) > 0;
  }
  bool holds(const Box& box) const {
    return box.min.x >= 0 && box.min.y >= 0 && box.max.x <= width_ && box.max.y <= height_;
  }

 private:
  // Clamped first, so truncating is flooring (and no call to floor).
  int column(double x) const { return std::min(static_cast<int>(std::clamp(x, 0.0, width_) * per_px_), columns_ - 1); }
  int row(double y) const { return std::min(static_cast<int>(std::clamp(y, 0.0, height_) * per_px_), rows_ - 1); }
  std::size_t at(int x, int y) const { return static_cast<std::size_t>(y * (columns_ + 1) + x); }
  // Counted cells in columns [x0, x1) and rows [y0, y1).
  std::int32_t count(int x0, int x1, int y0, int y1) const {
    if (x1 <= x0 || y1 <= y0) return 0;
    return sums_[at(x1, y1)] - sums_[at(x0, y1)] - sums_[at(x1, y0)] + sums_[at(x0, y0)];
  }

  double width_ = 0, height_ = 0;
  double per_px_ = 1.0;  // cells per pixel
  float per_px_f_ = 1.0f;
  int columns_ = 0, rows_ = 0;
  std::vector<std::uint8_t> counts_;
  std::vector<std::int32_t> sums_;
};

// An edge of the layers' outline: its ends' welded ids and places.
struct OutlineEdge {
  std::uint32_t from, to;
  const glm::dvec2* a;
  const glm::dvec2* b;
};

// What one call leaves for the next on the same thread: its buffers, so a
// frame allocates nothing (one per thread that runs the cull: the kept
// background thread, or the render thread where it runs the cull itself).
struct Scratch {
  std::vector<ProjectedVertex> vertices;
  std::vector<std::uint8_t> turns;  // FaceTurn per face
  std::vector<Box> boxes;
  std::vector<std::uint32_t> turned_away;
  CellCounts ends;
  CellCounts covered;
  CoverLayers layers;
  std::vector<OutlineEdge> outline;
  std::vector<std::int32_t> first_from;  // per welded position: an outline edge starting there
  std::vector<std::int32_t> next_from;   // per outline edge: another starting where it does
  std::vector<std::uint8_t> given;
};

bool in_depth_range(const glm::dvec4& clip) {
  return clip.w > 0.0 && std::abs(clip.z) <= clip.w && std::isfinite(clip.x) && std::isfinite(clip.y);
}

// How much a matrix stretches every vector, where it stretches them all
// alike (its columns orthogonal and of one length, to rounding).
std::optional<double> stretch_of_similarity(const glm::dmat3& m) {
  const glm::dmat3 squared = glm::transpose(m) * m;
  const double s2 = squared[0][0];
  constexpr double kRounding = 1e-12;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (std::abs(squared[i][j] - (i == j ? s2 : 0.0)) > kRounding * s2) return std::nullopt;
    }
  }
  return std::sqrt(s2);
}

// hull.vert in double for every vertex the level uses: the corner moves
// along its offset by at most the full width (its obliquity factor only
// shortens the move, and the moved point stays on the segment, whose image
// is a segment). False where a vertex or its corner lies outside the depth
// range or behind the eye, where the cut would end the cover.
bool project_vertices(const HullCullMesh& mesh, const HullCullView& view, std::vector<ProjectedVertex>& out) {
  const glm::dmat4 to_clip = view.clip * view.model;
  // The offset turned and taken to clip space in one product.
  const glm::dmat3x4 offset_to_clip = glm::dmat3x4(view.clip) * view.normal_matrix;
  const double px_per_world_at_w1 = view.width_px * view.world_per_px_at_w1;
  const glm::dvec2 half_viewport(0.5 * view.viewport_width, 0.5 * view.viewport_height);
  const auto window = [&](const glm::dvec4& clip) { return (glm::dvec2(clip) * (1.0 / clip.w) + 1.0) * half_viewport; };
  // Under a similarity every offset turns and keeps its length times the
  // same factor: no product and no square root per vertex.
  const std::optional<double> uniform_stretch = stretch_of_similarity(view.normal_matrix);
  for (std::uint32_t v : mesh.used_vertices()) {
    const glm::dvec4 clip = to_clip * glm::dvec4(glm::dvec3(mesh.position(v)), 1.0);
    const glm::dvec3 offset(mesh.outline_offset(v));
    const double length = mesh.outline_offset_length(v);
    const double turned_len = uniform_stretch ? *uniform_stretch * length : glm::length(view.normal_matrix * offset);
    const double distance = px_per_world_at_w1 * std::abs(clip.w);
    const double scale = turned_len > 0.0 ? length / turned_len * distance : 0.0;
    const glm::dvec4 moved = clip + offset_to_clip * (offset * scale);
    if (!in_depth_range(clip) || !in_depth_range(moved)) return false;
    ProjectedVertex& p = out[v];
    p.window = window(clip);
    const glm::dvec2 corner = window(moved);
    p.half_move = glm::vec2(window(0.5 * (clip + moved)));
    p.whole_move = glm::vec2(corner);
    p.reach_min = glm::vec2(glm::min(p.window, corner));
    p.reach_max = glm::vec2(glm::max(p.window, corner));
  }
  return true;
}

// The box round every vertex the level uses, where the main pass draws it.
std::pair<glm::dvec2, glm::dvec2> window_bounds(const HullCullMesh& mesh, std::span<const ProjectedVertex> vertices) {
  glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  for (std::uint32_t v : mesh.used_vertices()) {
    lo = glm::min(lo, vertices[v].window);
    hi = glm::max(hi, vertices[v].window);
  }
  return {lo, hi};
}

// Which way the face a, b, c turns where the winding `drawn_sign` (+1:
// counter-clockwise) is drawn: surely, where the sign of twice its area
// holds for any move of the corners within the slack (the sides' lengths
// are bounded by |dx| + |dy|), else unsure. Without branches: the faces of
// a level turn either way in no order a predictor could follow.
FaceTurn face_turn(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, double drawn_sign) {
  const glm::dvec2 ab = b - a, ac = c - a, bc = c - b;
  const double area2 = (ab.x * ac.y - ab.y * ac.x) * drawn_sign;
  // std::abs, not glm::abs: glm's compares and branches.
  const double sides =
      std::abs(ab.x) + std::abs(ab.y) + std::abs(ac.x) + std::abs(ac.y) + std::abs(bc.x) + std::abs(bc.y);
  const double doubt = 2.0 * kVertexSlackPx * sides + 4.0 * kVertexSlackPx * kVertexSlackPx;
  const int drawn = area2 > doubt;
  const int away = area2 < -doubt;
  return static_cast<FaceTurn>(drawn * kDrawn + (1 - drawn - away) * kUnsure);
}

// The outline's edges to the layers along its loops, each edge after the
// one that ends where it starts wherever there is one, so the layers count
// such pairs once.
void give_along_loops(std::span<const OutlineEdge> outline, std::size_t positions, Scratch& scratch) {
  std::vector<std::int32_t>& first_from = scratch.first_from;
  std::vector<std::int32_t>& next_from = scratch.next_from;
  std::vector<std::uint8_t>& given = scratch.given;
  first_from.assign(positions, -1);
  next_from.resize(outline.size());
  given.assign(outline.size(), 0);
  for (std::size_t e = 0; e < outline.size(); ++e) {
    next_from[e] = first_from[outline[e].from];
    first_from[outline[e].from] = static_cast<std::int32_t>(e);
  }
  for (std::size_t start = 0; start < outline.size(); ++start) {
    for (std::int32_t e = static_cast<std::int32_t>(start); e >= 0 && !given[static_cast<std::size_t>(e)];) {
      const OutlineEdge& edge = outline[static_cast<std::size_t>(e)];
      given[static_cast<std::size_t>(e)] = 1;
      scratch.layers.add_outline_edge(*edge.a, *edge.b);
      std::int32_t next = first_from[edge.to];
      while (next >= 0 && given[static_cast<std::size_t>(next)]) next = next_from[static_cast<std::size_t>(next)];
      e = next;
    }
  }
}

// Whether the hull face of a, b, c turns to the side whose signed area has
// the sign `side` wherever each corner lies between half and the whole of
// its move, by more than the slack. Twice the area is affine in each
// corner's place along its stretch, so the eight choices of the
// stretches' ends bound it; it is the sum of the cross products of
// consecutive corners, so those eight take eight products. Each side is
// longer than between the whole moves by at most its ends' stretches. In
// float, about the first corner's whole move, where its rounding is far
// below the slack.
bool hull_face_surely_turns(const ProjectedVertex& a, const ProjectedVertex& b, const ProjectedVertex& c, float side) {
  const auto cross = [](const glm::vec2& u, const glm::vec2& v) { return u.x * v.y - u.y * v.x; };
  // About a's whole move, a's half move is `a0` and its whole move 0.
  const glm::vec2 origin = a.whole_move;
  const glm::vec2 a0 = a.half_move - origin;
  const glm::vec2 b0 = b.half_move - origin, b1 = b.whole_move - origin;
  const glm::vec2 c0 = c.half_move - origin, c1 = c.whole_move - origin;
  // With a at 0 the area is cross(b, c); with a at a0 it adds
  // cross(a0, b) + cross(c, a0).
  const float bc00 = cross(b0, c0), bc01 = cross(b0, c1), bc10 = cross(b1, c0), bc11 = cross(b1, c1);
  const float ab0 = cross(a0, b0), ab1 = cross(a0, b1);
  const float ca0 = cross(c0, a0), ca1 = cross(c1, a0);
  const float f[8] = {bc00, bc01, bc10, bc11, bc00 + ab0 + ca0, bc01 + ab0 + ca1, bc10 + ab1 + ca0, bc11 + ab1 + ca1};
  float lowest = f[0], highest = f[0];
  for (const float v : f) {
    lowest = std::min(lowest, v);
    highest = std::max(highest, v);
  }
  const float least = side > 0.0f ? lowest : -highest;  // of the area times `side`
  const auto l1 = [](const glm::vec2& v) { return std::abs(v.x) + std::abs(v.y); };
  const float stretches = l1(a0) + l1(b1 - b0) + l1(c1 - c0);
  const float sides = l1(b1) + l1(c1) + l1(c1 - b1) + 2.0f * stretches;
  constexpr auto slack = static_cast<float>(kVertexSlackPx);
  return least > 2.0f * slack * sides + 4.0f * slack * slack;
}

// The sign of the signed area of the faces a draw culling `hidden` skips; 0
// where it skips none.
float skipped_side(HiddenFaces hidden) {
  switch (hidden) {
    case HiddenFaces::Back:
      return -1.0f;
    case HiddenFaces::Front:
      return 1.0f;
    case HiddenFaces::None:
      break;
  }
  return 0.0f;
}

// The faces the main pass draws, with a winding no rounding can flip, and
// the box round each face and its hull face.
void classify_faces(const HullCullMesh& mesh, const HullCullView& view, Scratch& scratch) {
  const std::span<const std::uint32_t> indices = mesh.indices();
  const std::size_t triangles = indices.size() / 3;
  const double drawn_sign = view.drawn_clockwise ? -1.0 : 1.0;
  scratch.turns.resize(triangles);
  scratch.boxes.resize(triangles);
  for (std::size_t t = 0; t < triangles; ++t) {
    const ProjectedVertex& a = scratch.vertices[indices[3 * t]];
    const ProjectedVertex& b = scratch.vertices[indices[3 * t + 1]];
    const ProjectedVertex& c = scratch.vertices[indices[3 * t + 2]];
    scratch.turns[t] = face_turn(a.window, b.window, c.window, drawn_sign);
    scratch.boxes[t].min = glm::min(glm::min(a.reach_min, b.reach_min), c.reach_min) - static_cast<float>(kMarginPx);
    scratch.boxes[t].max = glm::max(glm::max(a.reach_max, b.reach_max), c.reach_max) + static_cast<float>(kMarginPx);
  }
}

bool drawn(const Scratch& scratch, std::size_t t) { return scratch.turns[t] == kDrawn; }

// Where the drawn faces' cover may end (their edges not shared with another
// drawn face), where a point it holds lies (their middles), and how many
// layers of the drawn and unsure faces lie over each cell (their edges not
// shared within them).
void map_cover(const HullCullMesh& mesh, const HullCullView& view, Scratch& scratch) {
  const std::span<const std::uint32_t> indices = mesh.indices();
  const std::size_t triangles = indices.size() / 3;
  const double cell = cell_px(view, triangles);
  scratch.ends.reset(view.viewport_width, view.viewport_height, cell);
  scratch.covered.reset(view.viewport_width, view.viewport_height, cell);
  if (view.count_layers) {
    const std::pair<glm::dvec2, glm::dvec2> bounds = window_bounds(mesh, scratch.vertices);
    scratch.layers.reset({view.viewport_width, view.viewport_height, cell, bounds.first, bounds.second},
                         !view.drawn_clockwise, kVertexSlackPx);
  }
  scratch.outline.clear();
  for (std::size_t t = 0; t < triangles; ++t) {
    if (scratch.turns[t] == kTurnedAway) continue;
    const glm::dvec2* corner[3];
    for (std::size_t c = 0; c < 3; ++c) corner[c] = &scratch.vertices[indices[3 * t + c]].window;
    if (drawn(scratch, t)) scratch.covered.add_point((*corner[0] + *corner[1] + *corner[2]) / 3.0);
    for (int k = 0; k < 3; ++k) {
      const std::int32_t other = mesh.neighbour(t, k);
      const FaceTurn across =
          other >= 0 ? static_cast<FaceTurn>(scratch.turns[static_cast<std::size_t>(other)]) : kTurnedAway;
      const int k1 = (k + 1) % 3;
      if (drawn(scratch, t) && across != kDrawn) scratch.ends.add_box(*corner[k], *corner[k1]);
      if (view.count_layers && across == kTurnedAway) {
        scratch.outline.push_back(
            {mesh.welded(indices[3 * t + k]), mesh.welded(indices[3 * t + k1]), corner[k], corner[k1]});
      }
    }
  }
  scratch.ends.sum();
  scratch.covered.sum();
  if (view.count_layers) {
    give_along_loops(scratch.outline, scratch.vertices.size(), scratch);
    scratch.layers.finish();
  }
}

// A face whose box holds a covered point (its own face, if drawn, or a
// drawn face's middle) and meets no end of the cover lies wholly inside
// it, whichever way it or its hull face turns; so does one whose box the
// layers cover.
bool cannot_show(const Scratch& scratch, const HullCullView& view, std::size_t t) {
  const Box& box = scratch.boxes[t];
  if (!scratch.ends.holds(box)) return false;
  const CellRect cells = scratch.ends.overlapped_by(box);
  if (!scratch.ends.any(cells) && (drawn(scratch, t) || scratch.covered.any_inside(box))) return true;
  return view.count_layers && scratch.layers.covers(cells.x0, cells.x1, cells.y0, cells.y1);
}

// A face the main pass draws turns toward the camera, and so, all but
// always, does its hull face: only the others are worth the test.
bool hull_face_turned_away(const HullCullMesh& mesh, const Scratch& scratch, float skipped, std::size_t t) {
  const std::span<const std::uint32_t> indices = mesh.indices();
  return skipped != 0.0f && !drawn(scratch, t) &&
         hull_face_surely_turns(scratch.vertices[indices[3 * t]], scratch.vertices[indices[3 * t + 1]],
                                scratch.vertices[indices[3 * t + 2]], skipped);
}

// The faces that may show, submesh by submesh: first those the hull draws
// as they come, then, in ranges of their own, those it draws turned away.
HullSubset faces_that_may_show(const HullCullMesh& mesh, const HullCullView& view, Scratch& scratch) {
  const std::span<const std::uint32_t> indices = mesh.indices();
  const float skipped = skipped_side(view.hull_hidden);
  HullSubset out;
  out.indices.reserve(indices.size());
  // The faces set apart gather here, each submesh's range of them first
  // counted from its start, then moved behind the rest.
  std::vector<std::uint32_t>& away = scratch.turned_away;
  away.clear();
  for (const scene::Submesh& sub : mesh.submeshes()) {
    scene::Submesh kept{static_cast<std::uint32_t>(out.indices.size()), 0, sub.material};
    scene::Submesh set_apart{static_cast<std::uint32_t>(away.size()), 0, sub.material};
    for (std::size_t e = sub.first_index; e < sub.first_index + sub.index_count; e += 3) {
      if (cannot_show(scratch, view, e / 3)) {
        ++out.culled_triangles;
        continue;
      }
      std::vector<std::uint32_t>& to = hull_face_turned_away(mesh, scratch, skipped, e / 3) ? away : out.indices;
      to.insert(to.end(), indices.begin() + static_cast<std::ptrdiff_t>(e),
                indices.begin() + static_cast<std::ptrdiff_t>(e + 3));
    }
    kept.index_count = static_cast<std::uint32_t>(out.indices.size()) - kept.first_index;
    out.submeshes.push_back(kept);
    set_apart.index_count = static_cast<std::uint32_t>(away.size()) - set_apart.first_index;
    out.turned_away.push_back(set_apart);
  }
  if (away.empty()) {
    out.turned_away.clear();
    return out;
  }
  for (scene::Submesh& range : out.turned_away) range.first_index += static_cast<std::uint32_t>(out.indices.size());
  out.indices.insert(out.indices.end(), away.begin(), away.end());
  return out;
}

}  // namespace

HullCullMesh::HullCullMesh(Stream positions, Stream outline_offsets, std::span<const std::uint32_t> indices,
                           std::span<const scene::Submesh> submeshes)
    : positions_(std::move(positions)),
      offsets_(std::move(outline_offsets)),
      indices_(indices.begin(), indices.end()),
      submeshes_(submeshes.begin(), submeshes.end()) {
  used_ = indices_;
  std::sort(used_.begin(), used_.end());
  used_.erase(std::unique(used_.begin(), used_.end()), used_.end());
  offset_lengths_.resize(offsets_->size());
  for (std::size_t v = 0; v < offsets_->size(); ++v) offset_lengths_[v] = glm::length(glm::dvec3((*offsets_)[v]));
  welded_ = weld_by_position(*positions_, used_);
  neighbours_ = edge_neighbours(indices_, welded_);
}

std::optional<HullSubset> hull_faces_that_may_show(const HullCullMesh& mesh, const HullCullView& view) {
  if (view.viewport_width <= 0 || view.viewport_height <= 0) return std::nullopt;
  static thread_local Scratch scratch;
  scratch.vertices.resize(mesh.used_vertices().empty() ? 0 : mesh.used_vertices().back() + 1);
  if (!project_vertices(mesh, view, scratch.vertices)) return std::nullopt;
  classify_faces(mesh, view, scratch);
  map_cover(mesh, view, scratch);
  return faces_that_may_show(mesh, view, scratch);
}

}  // namespace toond::render
