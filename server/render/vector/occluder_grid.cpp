#include "render/vector/occluder_grid.h"

#include "render/vector/parallel_runs.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace toond::render::vector {
namespace {

// The plane n · p + d = 0 turned so that `inside` lies on its positive
// side, its normal made unit; false where it has no direction.
bool plane_through(glm::dvec3 n, double d_per_unit, const glm::dvec3& inside, glm::dvec4& plane) {
  const double length = glm::length(n);
  if (!(length > 0)) return false;
  n /= length;
  double d = d_per_unit / length;
  if (glm::dot(n, inside) + d < 0) {
    n = -n;
    d = -d;
  }
  plane = glm::dvec4(n, d);
  return true;
}

// Every point on screen, in pixels; NaN where it lies at or behind the eye
// (a triangle with such a corner has no box on screen).
std::vector<glm::dvec2> points_on_screen(const ViewMesh& mesh, const ScreenMap& screen) {
  std::vector<glm::dvec2> pixels(mesh.points.size());
  for_each_run(pixels.size(), 16384, [&](std::size_t, std::size_t first, std::size_t end) {
    for (std::size_t v = first; v < end; ++v) {
      const glm::dvec4 c = screen.clip(mesh.points[v]);
      pixels[v] = c.w > 1e-12 * std::abs(c.z)
                      ? glm::dvec2((c.x / c.w * 0.5 + 0.5) * screen.width, (0.5 - c.y / c.w * 0.5) * screen.height)
                      : glm::dvec2(std::numeric_limits<double>::quiet_NaN());
    }
  });
  return pixels;
}

// A triangle's screen box; false where a corner lies at or behind the eye.
bool screen_box(const ViewMesh& mesh, const std::vector<glm::dvec2>& pixels, std::size_t t, glm::dvec2& lo,
                glm::dvec2& hi) {
  lo = glm::dvec2(std::numeric_limits<double>::max());
  hi = -lo;
  for (int k = 0; k < 3; ++k) {
    const glm::dvec2 s = pixels[mesh.corners[3 * t + k]];
    if (std::isnan(s.x)) return false;
    lo = glm::min(lo, s);
    hi = glm::max(hi, s);
  }
  return true;
}

}  // namespace

bool make_occluder(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, bool orthographic, Occluder& out) {
  const glm::dvec3 v[3] = {a, b, c};
  const glm::dvec3 n = glm::cross(b - a, c - a);
  const double area2 = glm::length(n);
  if (!(area2 > 0)) return false;
  // The eye's side of the triangle's plane: the origin, or +z far away.
  const double eye_side = orthographic ? n.z / area2 : -glm::dot(n, a) / area2;
  if (!(std::abs(eye_side) > 1e-12 * (orthographic ? 1.0 : glm::length(a)))) return false;
  const double sign = eye_side > 0 ? -1.0 : 1.0;  // behind the plane: away from the eye
  out.planes[3] = glm::dvec4(n / area2, -glm::dot(n, a) / area2) * sign;
  for (int i = 0; i < 3; ++i) {
    const glm::dvec3& p = v[i];
    const glm::dvec3& q = v[(i + 1) % 3];
    const glm::dvec3& r = v[(i + 2) % 3];
    const bool ok = orthographic ? plane_through(glm::cross(q - p, glm::dvec3(0, 0, 1)),
                                                 -glm::dot(glm::cross(q - p, glm::dvec3(0, 0, 1)), p), r, out.planes[i])
                                 : plane_through(glm::cross(p, q), 0.0, r, out.planes[i]);
    if (!ok) return false;
  }
  out.near_depth = static_cast<float>(std::min({-a.z, -b.z, -c.z}));
  return true;
}

OccluderGrid::OccluderGrid(const ViewMesh& mesh, const ScreenMap& screen, double margin) {
  origin_ = glm::dvec2(-margin);
  const glm::dvec2 extent = glm::dvec2(screen.width, screen.height) + 2.0 * margin;
  std::size_t hiders = 0;
  for (std::uint8_t h : mesh.hides) hiders += h;
  // About one triangle's box a cell: a dense mesh's small triangles then
  // share cells with few others, a coarse one's large ones span few cells.
  cell_ = std::clamp(std::sqrt(extent.x * extent.y / static_cast<double>(std::max<std::size_t>(hiders, 1))), 2.0, 64.0);
  columns_ = std::max(1, static_cast<int>(std::ceil(extent.x / cell_)));
  rows_ = std::max(1, static_cast<int>(std::ceil(extent.y / cell_)));
  bin(place(mesh, screen));
}

std::vector<glm::ivec4> OccluderGrid::place(const ViewMesh& mesh, const ScreenMap& screen) {
  constexpr std::size_t kTrianglesPerRun = 8192;
  // Each hiding triangle's place in the list, counted ahead so that the runs
  // write their own stretch of it; one that hides nothing after all keeps
  // its place with no cells.
  const std::size_t runs = (mesh.triangle_count() + kTrianglesPerRun - 1) / kTrianglesPerRun;
  std::vector<std::size_t> first_of_run(runs + 1, 0);
  for (std::size_t run = 0; run < runs; ++run) {
    std::size_t hiders = 0;
    for (std::size_t t = run * kTrianglesPerRun; t < std::min(mesh.triangle_count(), (run + 1) * kTrianglesPerRun); ++t)
      hiders += mesh.hides[t];
    first_of_run[run + 1] = first_of_run[run] + hiders;
  }
  occluders_.resize(first_of_run.back());
  std::vector<glm::ivec4> ranges(first_of_run.back(), glm::ivec4(1, 0, 0, 0));
  std::vector<std::uint8_t> unbounded(first_of_run.back(), 0);
  const std::vector<glm::dvec2> pixels = points_on_screen(mesh, screen);
  for_each_run(mesh.triangle_count(), kTrianglesPerRun, [&](std::size_t run, std::size_t first, std::size_t end) {
    std::size_t at = first_of_run[run];
    for (std::size_t t = first; t < end; ++t) {
      if (!mesh.hides[t]) continue;
      const std::size_t i = at++;
      const glm::dvec3 v[3] = {mesh.corner(t, 0), mesh.corner(t, 1), mesh.corner(t, 2)};
      Occluder& o = occluders_[i];
      if (!make_occluder(v[0], v[1], v[2], mesh.orthographic, o)) continue;
      for (int k = 0; k < 3; ++k) o.groups[k] = mesh.groups[mesh.corners[3 * t + k]];
      o.shared_sides = mesh.shared_sides[t];
      glm::dvec2 lo, hi;
      if (screen_box(mesh, pixels, t, lo, hi)) {
        ranges[i] = cell_range(lo, hi);  // empty off the drawn area
        o.box_min = glm::vec2(lo);
        o.box_max = glm::vec2(hi);
      } else {
        unbounded[i] = 1;
        o.box_min = glm::vec2(-std::numeric_limits<float>::max());
        o.box_max = glm::vec2(std::numeric_limits<float>::max());
      }
    }
  });
  for (std::uint32_t i = 0; i < unbounded.size(); ++i) {
    if (unbounded[i]) everywhere_.push_back(i);
  }
  return ranges;
}

void OccluderGrid::bin(const std::vector<glm::ivec4>& ranges) {
  // Counted, then filled: one flat list of every cell's occluders.
  cell_start_.assign(static_cast<std::size_t>(columns_) * rows_ + 1, 0);
  for (const glm::ivec4& r : ranges) {
    for (int y = r.y; y <= r.w; ++y) {
      for (int x = r.x; x <= r.z; ++x) ++cell_start_[static_cast<std::size_t>(y) * columns_ + x + 1];
    }
  }
  for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
  cell_items_.resize(cell_start_.back());
  std::vector<std::uint32_t> filled(cell_start_.begin(), cell_start_.end() - 1);
  for (std::uint32_t i = 0; i < ranges.size(); ++i) {
    const glm::ivec4& r = ranges[i];
    for (int y = r.y; y <= r.w; ++y) {
      for (int x = r.x; x <= r.z; ++x) cell_items_[filled[static_cast<std::size_t>(y) * columns_ + x]++] = i;
    }
  }
}

glm::ivec4 OccluderGrid::cell_range(glm::dvec2 lo, glm::dvec2 hi) const {
  // Clamped to one cell past either side before the conversion, so that a
  // box far off the grid stays an empty range.
  const auto cell_of = [&](double v, double origin, int cells) {
    return static_cast<int>(std::clamp(std::floor((v - origin) / cell_), -1.0, static_cast<double>(cells)));
  };
  return glm::ivec4(std::max(0, cell_of(lo.x, origin_.x, columns_)), std::max(0, cell_of(lo.y, origin_.y, rows_)),
                    std::min(columns_ - 1, cell_of(hi.x, origin_.x, columns_)),
                    std::min(rows_ - 1, cell_of(hi.y, origin_.y, rows_)));
}

double OccluderGrid::first_depth(glm::dvec2 px, const ScreenMap& screen, std::vector<std::uint32_t>& nearby,
                                 GatherScratch& scratch) const {
  gather(px, px, nearby, scratch);
  const glm::dvec3 from = screen.unproject(px, -1.0);
  const glm::dvec3 along = screen.unproject(px, 1.0) - from;
  double nearest = -1;
  for (std::uint32_t i : nearby) {
    const Occluder& o = occluders_[i];
    bool inside = true;
    for (int k = 0; k < 3 && inside; ++k) inside = glm::dot(glm::dvec3(o.planes[k]), from) + o.planes[k].w > 0;
    const glm::dvec3 n(o.planes[3]);
    const double rate = glm::dot(n, along);
    if (!inside || rate == 0) continue;
    const double depth = -(from + along * (-(glm::dot(n, from) + o.planes[3].w) / rate)).z;
    if (nearest < 0 || depth < nearest) nearest = depth;
  }
  return nearest;
}

void OccluderGrid::gather(glm::dvec2 p, glm::dvec2 q, std::vector<std::uint32_t>& out, GatherScratch& scratch) const {
  out.clear();
  if (scratch.seen.size() != occluders_.size() || scratch.mark == std::numeric_limits<std::uint32_t>::max()) {
    scratch.seen.assign(occluders_.size(), 0);
    scratch.mark = 0;
  }
  ++scratch.mark;
  const auto take = [&](std::uint32_t i) {
    if (scratch.seen[i] == scratch.mark) return;
    scratch.seen[i] = scratch.mark;
    out.push_back(i);
  };
  for (std::uint32_t i : everywhere_) take(i);
  if (p.y > q.y) std::swap(p, q);
  const glm::ivec4 span = cell_range(glm::min(p, q), glm::max(p, q));
  // Row by row, the columns the segment crosses within the row's height.
  for (int row = span.y; row <= span.w; ++row) {
    const double y0 = std::max(p.y, origin_.y + row * cell_);
    const double y1 = std::min(q.y, origin_.y + (row + 1) * cell_);
    double x0 = p.x, x1 = q.x;
    if (q.y - p.y > 1e-12) {
      x0 = p.x + (q.x - p.x) * (y0 - p.y) / (q.y - p.y);
      x1 = p.x + (q.x - p.x) * (y1 - p.y) / (q.y - p.y);
    }
    const glm::ivec4 cols =
        cell_range(glm::dvec2(std::min(x0, x1) - 1e-6, y0), glm::dvec2(std::max(x0, x1) + 1e-6, y0));
    for (int col = cols.x; col <= cols.z; ++col) {
      const std::size_t cell = static_cast<std::size_t>(row) * columns_ + col;
      for (std::uint32_t k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) take(cell_items_[k]);
    }
  }
}

}  // namespace toond::render::vector
