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

// The entries in a 2-d tree whose nodes count the entries left under
// them, for the nearest one to a point: a drawn stroke's entries leave,
// and emptied branches are never searched again, so a walk that must come
// back from far away for a stray stroke costs about a logarithm, not a
// sweep over the emptied page.
class EntryTree {
 public:
  static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

  // `entries`: each path's together, in the order of the paths.
  EntryTree(std::vector<Entry> entries, std::size_t paths)
      : entries_(std::move(entries)), first_entry_(paths + 1, 0), slot_of_(entries_.size(), 0) {
    for (const Entry& e : entries_) ++first_entry_[e.path + 1];
    for (std::size_t p = 0; p < paths; ++p) first_entry_[p + 1] += first_entry_[p];
    slots_.reserve(entries_.size());
    for (std::uint32_t i = 0; i < entries_.size(); ++i) slots_.push_back({entries_[i].at, i, kNone, true});
    if (!slots_.empty()) build(0, static_cast<std::uint32_t>(slots_.size()), kNone, 0);
    for (std::uint32_t k = 0; k < slots_.size(); ++k) slot_of_[slots_[k].entry] = k;
  }

  // The nearest entry to `from` of a path not yet taken (of equally near
  // ones the first), into `near`; false when none is left. `near` on the
  // way in: an entry near `from` (the last one taken; else kNone), whose
  // leaf is searched first so that the search from the root has a near
  // best to cut branches with.
  bool nearest(glm::dvec2 from, std::uint32_t& near) const {
    Search search{from};
    if (near < slot_of_.size()) scan_leaf(nodes_[slots_[slot_of_[near]].leaf], search);
    if (!nodes_.empty()) visit(0, search);
    near = search.best_entry;
    return near != kNone;
  }
  const Entry& entry(std::uint32_t i) const { return entries_[i]; }

  // The path's entries out of the tree: it is drawn.
  void take(std::uint32_t path) {
    for (std::uint32_t i = first_entry_[path]; i < first_entry_[path + 1]; ++i) {
      Slot& slot = slots_[slot_of_[i]];
      if (!slot.alive) continue;
      slot.alive = false;
      for (std::uint32_t n = slot.leaf; n != kNone; n = nodes_[n].parent) --nodes_[n].alive;
    }
  }

 private:
  static constexpr std::uint32_t kLeafSize = 16;

  // An entry where the tree keeps it: each node's together.
  struct Slot {
    glm::dvec2 at;
    std::uint32_t entry;
    std::uint32_t leaf;
    bool alive;
  };
  struct Node {
    glm::dvec2 lo{0.0}, hi{0.0};       // the box around its entries
    std::uint32_t begin = 0, end = 0;  // its slots
    std::uint32_t parent = kNone;
    std::uint32_t low = kNone, high = kNone;  // children; kNone: a leaf
    std::uint32_t alive = 0;
  };
  struct Search {
    glm::dvec2 from;
    double best = std::numeric_limits<double>::max();
    std::uint32_t best_entry = kNone;
  };

  // The node over slots_[begin, end), split at the median along x at even
  // depths and y at odd ones; its box from its slots at a leaf, else from
  // its children's.
  std::uint32_t build(std::uint32_t begin, std::uint32_t end, std::uint32_t parent, int depth) {
    const auto n = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back({});
    nodes_[n].begin = begin;
    nodes_[n].end = end;
    nodes_[n].parent = parent;
    nodes_[n].alive = end - begin;
    if (end - begin <= kLeafSize) {
      glm::dvec2 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
      for (std::uint32_t k = begin; k < end; ++k) {
        slots_[k].leaf = n;
        lo = glm::min(lo, slots_[k].at);
        hi = glm::max(hi, slots_[k].at);
      }
      nodes_[n].lo = lo;
      nodes_[n].hi = hi;
      return n;
    }
    const int axis = depth % 2;
    const std::uint32_t middle = begin + (end - begin) / 2;
    std::nth_element(slots_.begin() + begin, slots_.begin() + middle, slots_.begin() + end,
                     [axis](const Slot& a, const Slot& b) { return a.at[axis] < b.at[axis]; });
    const std::uint32_t low = build(begin, middle, n, depth + 1);
    const std::uint32_t high = build(middle, end, n, depth + 1);
    Node& node = nodes_[n];
    node.low = low;
    node.high = high;
    node.lo = glm::min(nodes_[low].lo, nodes_[high].lo);
    node.hi = glm::max(nodes_[low].hi, nodes_[high].hi);
    return n;
  }

  static double distance2_to_box(glm::dvec2 p, const Node& node) {
    const glm::dvec2 d = glm::max(glm::max(node.lo - p, p - node.hi), glm::dvec2(0.0));
    return glm::dot(d, d);
  }

  void scan_leaf(const Node& leaf, Search& search) const {
    for (std::uint32_t k = leaf.begin; k < leaf.end; ++k) {
      const Slot& slot = slots_[k];
      if (!slot.alive) continue;
      const glm::dvec2 d = slot.at - search.from;
      const double d2 = glm::dot(d, d);
      if (d2 < search.best || (d2 == search.best && slot.entry < search.best_entry)) {
        search.best = d2;
        search.best_entry = slot.entry;
      }
    }
  }

  void visit(std::uint32_t n, Search& search) const {
    const Node& node = nodes_[n];
    // A box as far as the best so far may still hold an earlier entry as near.
    if (node.alive == 0 || distance2_to_box(search.from, node) > search.best) return;
    if (node.low == kNone) {
      scan_leaf(node, search);
      return;
    }
    const bool low_first =
        distance2_to_box(search.from, nodes_[node.low]) <= distance2_to_box(search.from, nodes_[node.high]);
    visit(low_first ? node.low : node.high, search);
    visit(low_first ? node.high : node.low, search);
  }

  std::vector<Entry> entries_;
  std::vector<std::uint32_t> first_entry_;  // per path, and one past the last
  std::vector<std::uint32_t> slot_of_;      // per entry
  std::vector<Slot> slots_;
  std::vector<Node> nodes_;
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
  EntryTree tree(entries_of(paths), paths.size());
  std::vector<Polyline> ordered;
  ordered.reserve(paths.size());
  glm::dvec2 pen(0.0);
  std::uint32_t near = EntryTree::kNone;
  while (tree.nearest(pen, near)) {
    const Entry& next = tree.entry(near);
    tree.take(next.path);
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
