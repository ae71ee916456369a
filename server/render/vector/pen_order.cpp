#include "render/vector/pen_order.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace toond::render::vector {
namespace {

// A point a stroke may be entered at.
struct Entry {
  glm::dvec2 at;
  std::uint32_t path;
  std::uint32_t vertex;
};

// The entries over a grid of cells, for the nearest one to a point.
class EntryGrid {
 public:
  explicit EntryGrid(std::vector<Entry> entries) : entries_(std::move(entries)) {
    glm::dvec2 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
    for (const Entry& e : entries_) {
      lo = glm::min(lo, e.at);
      hi = glm::max(hi, e.at);
    }
    origin_ = lo;
    const glm::dvec2 extent = glm::max(hi - lo, glm::dvec2(1.0));
    cell_ =
        std::max(std::sqrt(extent.x * extent.y / static_cast<double>(std::max<std::size_t>(entries_.size(), 1))), 1.0);
    columns_ = static_cast<int>(extent.x / cell_) + 1;
    rows_ = static_cast<int>(extent.y / cell_) + 1;
    cells_.resize(static_cast<std::size_t>(columns_) * rows_);
    for (std::uint32_t i = 0; i < entries_.size(); ++i) cells_[cell_index(entries_[i].at)].push_back(i);
  }

  // The nearest entry to `from` of a path not yet `done`; false when none is left.
  bool nearest(glm::dvec2 from, const std::vector<bool>& done, Entry& found) const {
    const glm::ivec2 c = cell_of(from);
    double best = std::numeric_limits<double>::max();
    std::uint32_t best_index = 0;
    const int reach = std::max({c.x, columns_ - 1 - c.x, c.y, rows_ - 1 - c.y});
    for (int ring = 0; ring <= reach; ++ring) {
      // Nothing in this ring or beyond lies nearer than its inner side.
      const double ring_distance = (ring - 1) * cell_;
      if (ring_distance > 0 && ring_distance * ring_distance > best) break;
      for (int y = c.y - ring; y <= c.y + ring; ++y) {
        for (int x = c.x - ring; x <= c.x + ring; ++x) {
          if (std::max(std::abs(x - c.x), std::abs(y - c.y)) != ring) continue;
          if (x < 0 || y < 0 || x >= columns_ || y >= rows_) continue;
          for (std::uint32_t i : cells_[static_cast<std::size_t>(y) * columns_ + x]) {
            const Entry& e = entries_[i];
            if (done[e.path]) continue;
            const glm::dvec2 d = e.at - from;
            const double d2 = glm::dot(d, d);
            // Ties go to the earlier entry, so the order never depends on the grid.
            if (d2 < best || (d2 == best && i < best_index)) {
              best = d2;
              best_index = i;
              found = e;
            }
          }
        }
      }
    }
    return best < std::numeric_limits<double>::max();
  }

 private:
  glm::ivec2 cell_of(glm::dvec2 p) const {
    const glm::dvec2 c = glm::floor((p - origin_) / cell_);
    return {std::clamp(static_cast<int>(std::clamp(c.x, -1.0, 1e9)), 0, columns_ - 1),
            std::clamp(static_cast<int>(std::clamp(c.y, -1.0, 1e9)), 0, rows_ - 1)};
  }
  std::size_t cell_index(glm::dvec2 p) const {
    const glm::ivec2 c = cell_of(p);
    return static_cast<std::size_t>(c.y) * columns_ + c.x;
  }

  std::vector<Entry> entries_;
  std::vector<std::vector<std::uint32_t>> cells_;
  glm::dvec2 origin_{0.0};
  double cell_ = 1;
  int columns_ = 1, rows_ = 1;
};

std::vector<Entry> entries_of(const std::vector<Polyline>& paths) {
  std::vector<Entry> entries;
  for (std::uint32_t p = 0; p < paths.size(); ++p) {
    const Polyline& line = paths[p];
    if (line.points.empty()) continue;
    if (line.closed) {
      for (std::uint32_t v = 0; v < line.points.size(); ++v) entries.push_back({line.points[v], p, v});
    } else {
      entries.push_back({line.points.front(), p, 0});
      if (line.points.size() > 1) {
        entries.push_back({line.points.back(), p, static_cast<std::uint32_t>(line.points.size() - 1)});
      }
    }
  }
  return entries;
}

// The path drawn from its entry: reversed when entered at its end, a
// closed one turned to start there.
Polyline entered_at(Polyline line, std::uint32_t vertex) {
  if (line.closed) {
    std::rotate(line.points.begin(), line.points.begin() + vertex, line.points.end());
  } else if (vertex != 0) {
    std::reverse(line.points.begin(), line.points.end());
  }
  return line;
}

glm::dvec2 end_of(const Polyline& line) { return line.closed ? line.points.front() : line.points.back(); }

}  // namespace

void order_for_pen(std::vector<Polyline>& paths) {
  std::erase_if(paths, [](const Polyline& p) { return p.points.empty(); });
  if (paths.size() < 2) return;
  const EntryGrid grid(entries_of(paths));
  std::vector<bool> done(paths.size(), false);
  std::vector<Polyline> ordered;
  ordered.reserve(paths.size());
  glm::dvec2 pen(0.0);
  Entry next{};
  while (grid.nearest(pen, done, next)) {
    done[next.path] = true;
    ordered.push_back(entered_at(std::move(paths[next.path]), next.vertex));
    pen = end_of(ordered.back());
  }
  paths = std::move(ordered);
}

double pen_up_travel(const std::vector<Polyline>& paths) {
  double travel = 0;
  glm::dvec2 pen(0.0);
  for (const Polyline& line : paths) {
    if (line.points.empty()) continue;
    travel += glm::length(line.points.front() - pen);
    pen = end_of(line);
  }
  return travel;
}

}  // namespace toond::render::vector
