#include "render/vector/stroke_chains.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace toond::render::vector {
namespace {

// Which pieces meet at each node, in one flat list.
struct Incidence {
  std::vector<std::uint32_t> start;  // per node, into `pieces` (one more at the end)
  std::vector<std::uint32_t> pieces;
};

Incidence incidence_of(const std::vector<StrokePiece>& pieces, std::uint32_t node_count) {
  Incidence inc;
  inc.start.assign(static_cast<std::size_t>(node_count) + 1, 0);
  for (const StrokePiece& p : pieces) {
    ++inc.start[p.node0 + 1];
    ++inc.start[p.node1 + 1];
  }
  for (std::size_t n = 1; n < inc.start.size(); ++n) inc.start[n] += inc.start[n - 1];
  inc.pieces.resize(inc.start.back());
  std::vector<std::uint32_t> filled(inc.start.begin(), inc.start.end() - 1);
  for (std::uint32_t i = 0; i < pieces.size(); ++i) {
    inc.pieces[filled[pieces[i].node0]++] = i;
    inc.pieces[filled[pieces[i].node1]++] = i;
  }
  return inc;
}

class Walker {
 public:
  Walker(const std::vector<StrokePiece>& pieces, std::uint32_t node_count)
      : pieces_(pieces), inc_(incidence_of(pieces, node_count)), used_(pieces.size(), false) {}

  std::vector<Polyline> walk_all() {
    std::vector<Polyline> out;
    // Odd ends first: a walk from a point with an odd number of pieces left
    // leaves it an even number, which later walks pass through.
    for (std::uint32_t i = 0; i < pieces_.size(); ++i) {
      for (std::uint32_t node : {pieces_[i].node0, pieces_[i].node1}) {
        while (unused_at(node) % 2 == 1) {
          out.push_back(walk_from(node));
        }
      }
    }
    for (std::uint32_t i = 0; i < pieces_.size(); ++i) {
      if (!used_[i]) out.push_back(walk_from(pieces_[i].node0));
    }
    return out;
  }

 private:
  static constexpr std::uint32_t kNone = 0xffffffffu;

  std::uint32_t unused_at(std::uint32_t node) const {
    std::uint32_t count = 0;
    for (std::uint32_t k = inc_.start[node]; k < inc_.start[node + 1]; ++k) count += used_[inc_.pieces[k]] ? 0 : 1;
    return count;
  }

  // The unused piece at `node` that goes on most nearly along `heading`
  // (any, the first, without one).
  std::uint32_t next_unused(std::uint32_t node, glm::dvec2 heading, bool has_heading) const {
    std::uint32_t best = kNone;
    double best_turn = -2;
    for (std::uint32_t k = inc_.start[node]; k < inc_.start[node + 1]; ++k) {
      const std::uint32_t i = inc_.pieces[k];
      if (used_[i]) continue;
      if (!has_heading) return i;
      const StrokePiece& p = pieces_[i];
      const glm::dvec2 step = p.node0 == node ? p.p1 - p.p0 : p.p0 - p.p1;
      const double len = glm::length(step);
      const double along = len > 0 ? glm::dot(step / len, heading) : -1.0;
      if (along > best_turn) {
        best_turn = along;
        best = i;
      }
    }
    return best;
  }

  Polyline walk_from(std::uint32_t start) {
    Polyline line;
    std::uint32_t node = start;
    glm::dvec2 heading(0.0);
    bool has_heading = false;
    for (std::uint32_t i = next_unused(node, heading, false); i != kNone; i = next_unused(node, heading, has_heading)) {
      used_[i] = true;
      const StrokePiece& p = pieces_[i];
      const bool forward = p.node0 == node;
      const glm::dvec2 from = forward ? p.p0 : p.p1;
      const glm::dvec2 to = forward ? p.p1 : p.p0;
      if (line.points.empty()) line.points.push_back(from);
      line.points.push_back(to);
      node = forward ? p.node1 : p.node0;
      const double len = glm::length(to - from);
      if (len > 0) {
        heading = (to - from) / len;
        has_heading = true;
      }
    }
    if (node == start && line.points.size() > 2) {
      line.closed = true;
      line.points.pop_back();
    }
    return line;
  }

  const std::vector<StrokePiece>& pieces_;
  Incidence inc_;
  std::vector<bool> used_;
};

// The open strokes' ends in cells `gap` wide, for the ones near a point.
class EndIndex {
 public:
  EndIndex(const std::vector<Polyline>& strokes, double gap) : strokes_(strokes), gap_(gap) {
    for (std::uint32_t i = 0; i < strokes.size(); ++i) {
      if (strokes[i].closed || strokes[i].points.size() < 2) continue;
      cells_[key(strokes[i].points.front())].push_back(2 * i);
      cells_[key(strokes[i].points.back())].push_back(2 * i + 1);
    }
  }

  // The nearest end (2 × stroke + 1 for its last point) within the gap of
  // p of a stroke not `used`; -1 where there is none.
  std::int64_t nearest(glm::dvec2 p, const std::vector<bool>& used) const {
    std::int64_t best = -1;
    double best_d = gap_;
    const auto [cx, cy] = cell(p);
    for (std::int64_t dy = -1; dy <= 1; ++dy) {
      for (std::int64_t dx = -1; dx <= 1; ++dx) {
        const auto it = cells_.find(pack(cx + dx, cy + dy));
        if (it == cells_.end()) continue;
        for (std::uint32_t end : it->second) {
          if (used[end / 2]) continue;
          const Polyline& s = strokes_[end / 2];
          const double d = glm::length((end % 2 ? s.points.back() : s.points.front()) - p);
          if (d <= best_d && (best < 0 || d < best_d || end < best)) {
            best_d = d;
            best = end;
          }
        }
      }
    }
    return best;
  }

 private:
  std::pair<std::int64_t, std::int64_t> cell(glm::dvec2 p) const {
    return {static_cast<std::int64_t>(std::floor(p.x / gap_)), static_cast<std::int64_t>(std::floor(p.y / gap_))};
  }
  static std::int64_t pack(std::int64_t x, std::int64_t y) {
    // Unsigned: wrapping is the mixing, not an overflow.
    return static_cast<std::int64_t>(static_cast<std::uint64_t>(x) * 1000003u + static_cast<std::uint64_t>(y));
  }
  std::int64_t key(glm::dvec2 p) const {
    const auto [x, y] = cell(p);
    return pack(x, y);
  }

  const std::vector<Polyline>& strokes_;
  double gap_;
  std::unordered_map<std::int64_t, std::vector<std::uint32_t>> cells_;
};

// Appends strokes to `line`'s end while one starts or ends near it.
void extend_end(Polyline& line, std::vector<Polyline>& strokes, const EndIndex& index, std::vector<bool>& used) {
  for (std::int64_t end = index.nearest(line.points.back(), used); end >= 0;
       end = index.nearest(line.points.back(), used)) {
    used[static_cast<std::size_t>(end / 2)] = true;
    std::vector<glm::dvec2>& next = strokes[static_cast<std::size_t>(end / 2)].points;
    if (end % 2) std::reverse(next.begin(), next.end());
    line.points.insert(line.points.end(), next.begin(), next.end());
  }
}

}  // namespace

std::vector<Polyline> stitch_strokes(std::vector<Polyline> strokes, double gap) {
  const EndIndex index(strokes, gap);
  std::vector<bool> used(strokes.size(), false);
  std::vector<Polyline> out;
  for (std::size_t i = 0; i < strokes.size(); ++i) {
    if (used[i]) continue;
    used[i] = true;
    Polyline line = std::move(strokes[i]);
    if (!line.closed && line.points.size() >= 2) {
      extend_end(line, strokes, index, used);
      std::reverse(line.points.begin(), line.points.end());
      extend_end(line, strokes, index, used);
      if (line.points.size() > 3 && glm::length(line.points.back() - line.points.front()) <= gap) {
        line.closed = true;
        line.points.pop_back();
      }
    }
    out.push_back(std::move(line));
  }
  return out;
}

std::vector<Polyline> chain_strokes(const std::vector<StrokePiece>& pieces, std::uint32_t node_count) {
  return Walker(pieces, node_count).walk_all();
}

}  // namespace toond::render::vector
