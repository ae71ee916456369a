#include "scene/mesh/intersection_lines.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <optional>

#include "scene/mesh/mesh_processing.h"
#include "scene/mesh/model.h"

namespace toond::scene {
namespace {

// As for crease edges: a seam turning by no more than the smallest crease
// angle a request may ask for is creased at no angle.
constexpr int kLeastTurnDeg = 1;
// Of the bounding box's diagonal: corners this near a plane lie in it,
// stretches this short are points.
constexpr double kTolerance = 1e-6;
// Planes whose normals' cross product is shorter than this (0.06°) are
// parallel: where they meet is no line to speak of.
constexpr double kLeastSine = 1e-3;
// Leaves of the tree of triangle boxes hold at most this many.
constexpr std::uint32_t kLeafTriangles = 4;
// The deadline is read on the first comparison and every this many after.
constexpr std::size_t kWorkBetweenTimeChecks = 65536;
constexpr std::uint32_t kMixedParts = std::numeric_limits<std::uint32_t>::max();

class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0u); }
  std::uint32_t root(std::uint32_t x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  void join(std::uint32_t a, std::uint32_t b) {
    a = root(a);
    b = root(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<std::uint32_t> parent_;
};

struct SearchBox {
  glm::dvec3 min{std::numeric_limits<double>::max()};
  glm::dvec3 max{std::numeric_limits<double>::lowest()};

  void add(const glm::dvec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void add(const SearchBox& other) {
    min = glm::min(min, other.min);
    max = glm::max(max, other.max);
  }
  bool overlaps(const SearchBox& other) const {
    return min.x <= other.max.x && other.min.x <= max.x && min.y <= other.max.y && other.min.y <= max.y &&
           min.z <= other.max.z && other.min.z <= max.z;
  }
  double size() const { return glm::length(max - min); }
};

struct Triangle {
  glm::dvec3 corners[3];
  glm::dvec3 normal;  // unit, by the winding
  std::uint32_t first_index = 0;
  std::uint32_t part = 0;
  SearchBox box;  // grown by the tolerance, so that touching boxes overlap
};

// A node of the tree of triangle boxes: a leaf holds `count` triangles
// from `first` of the tree's order; an inner node (count 0) two children.
struct Node {
  SearchBox box;
  std::uint32_t first = 0;
  std::uint32_t count = 0;
  std::uint32_t left = 0;
  std::uint32_t right = 0;
  std::uint32_t part = kMixedParts;  // the part all its triangles belong to, if one
};

// Where a plane cuts a triangle: the one or two points of it in the plane,
// and whether those are a whole edge of it (the plane only touches it).
struct Cut {
  glm::dvec3 ends[2];
  int count = 0;
  bool along_edge = false;
  bool coplanar = false;  // the whole triangle lies in the plane
};

Cut cut_by_plane(const glm::dvec3 (&v)[3], const glm::dvec3& normal, const glm::dvec3& on_plane, double tolerance) {
  double d[3];
  int side[3];
  for (int k = 0; k < 3; ++k) {
    d[k] = glm::dot(normal, v[k] - on_plane);
    side[k] = d[k] > tolerance ? 1 : d[k] < -tolerance ? -1 : 0;
  }
  Cut cut;
  if (side[0] == side[1] && side[1] == side[2]) {
    cut.coplanar = side[0] == 0;
    return cut;
  }
  int in_plane = 0;
  const auto add = [&cut](const glm::dvec3& p) {
    if (cut.count < 2) cut.ends[cut.count++] = p;
  };
  for (int k = 0; k < 3; ++k) {
    if (side[k] == 0) {
      add(v[k]);
      ++in_plane;
    }
  }
  for (int k = 0; k < 3; ++k) {
    const int j = (k + 1) % 3;
    if (side[k] * side[j] < 0) add(v[k] + (v[j] - v[k]) * (d[k] / (d[k] - d[j])));
  }
  cut.along_edge = in_plane == 2;
  return cut;
}

// The shading normal at `p` of the triangle at `first_index`, from its
// corners' (by p's barycentric weights, clamped to the triangle).
glm::dvec3 shading_normal_at(const glm::dvec3& p, const Triangle& t, std::span<const glm::vec3> normals,
                             std::span<const std::uint32_t> indices) {
  const glm::dvec3 e0 = t.corners[1] - t.corners[0], e1 = t.corners[2] - t.corners[0], e2 = p - t.corners[0];
  const double d00 = glm::dot(e0, e0), d01 = glm::dot(e0, e1), d11 = glm::dot(e1, e1);
  const double d20 = glm::dot(e2, e0), d21 = glm::dot(e2, e1);
  const double det = d00 * d11 - d01 * d01;
  glm::dvec3 w(1.0 / 3.0);
  if (det > 0.0) {
    const double v = (d11 * d20 - d01 * d21) / det, u = (d00 * d21 - d01 * d20) / det;
    w = glm::clamp(glm::dvec3(1.0 - v - u, v, u), 0.0, 1.0);
  }
  glm::dvec3 n(0.0);
  for (int k = 0; k < 3; ++k) n += w[k] * glm::dvec3(normals[indices[t.first_index + k]]);
  const double length = glm::length(n);
  return length > 0.0 ? n / length : t.normal;
}

double turn_deg(const glm::dvec3& a, const glm::dvec3& b) {
  return std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) * 180.0 / std::acos(-1.0);
}

// A segment found, before the segments are sorted.
struct FoundSeam {
  glm::vec3 points[4];  // p1, a, b, p2
  int turn = 0;         // whole degrees, rounded up
  double length = 0;
  // The two triangles' planes (unit normal, offset along it), and where a
  // and b lie along the line they meet in (normal 1 × normal 2).
  glm::dvec4 plane1{0.0};
  glm::dvec4 plane2{0.0};
  double from = 0;
  double to = 0;
};

// The stretch of the line where the planes of t1 and t2 meet that both
// hold, as a segment, when it is one (see the header).
std::optional<FoundSeam> crossing(const Triangle& t1, const Triangle& t2, double tolerance) {
  const Cut c1 = cut_by_plane(t1.corners, t2.normal, t2.corners[0], tolerance);
  if (c1.coplanar || c1.count < 2) return std::nullopt;
  const Cut c2 = cut_by_plane(t2.corners, t1.normal, t1.corners[0], tolerance);
  if (c2.coplanar || c2.count < 2 || (c1.along_edge && c2.along_edge)) return std::nullopt;
  const glm::dvec3 line = glm::cross(t1.normal, t2.normal);
  const double sine = glm::length(line);
  if (sine < kLeastSine) return std::nullopt;
  const glm::dvec3 along = line / sine;
  // Each cut as an interval along the line, its ends in order.
  const auto interval = [&along](const Cut& c) {
    const double s = glm::dot(along, c.ends[0]), t = glm::dot(along, c.ends[1]);
    return s <= t ? std::pair{std::pair{s, c.ends[0]}, std::pair{t, c.ends[1]}}
                  : std::pair{std::pair{t, c.ends[1]}, std::pair{s, c.ends[0]}};
  };
  const auto [low1, high1] = interval(c1);
  const auto [low2, high2] = interval(c2);
  const auto& low = low1.first >= low2.first ? low1 : low2;
  const auto& high = high1.first <= high2.first ? high1 : high2;
  if (high.first - low.first <= tolerance) return std::nullopt;
  const glm::dvec3 a = low.second, b = high.second;
  const double length = glm::length(b - a);
  if (!(length > tolerance)) return std::nullopt;
  FoundSeam found;
  const glm::dvec3 middle = 0.5 * (a + b);
  // Off the segment in each plane, on the side that makes (a, b, p) wind
  // as its triangle does, as far as the triangle reaches (at least the
  // segment's length): a piece of a seam cut short by a triangle edge
  // still gives the shader planes it can tell apart in float.
  const auto off = [&](const Triangle& t) {
    const double reach =
        std::max({length, glm::distance(t.corners[0], t.corners[1]), glm::distance(t.corners[1], t.corners[2]),
                  glm::distance(t.corners[2], t.corners[0])});
    return glm::vec3(middle + glm::normalize(glm::cross(t.normal, along)) * reach);
  };
  found.points[0] = off(t1);
  found.points[1] = glm::vec3(a);
  found.points[2] = glm::vec3(b);
  found.points[3] = off(t2);
  found.length = length;
  found.plane1 = glm::dvec4(t1.normal, glm::dot(t1.normal, t1.corners[0]));
  found.plane2 = glm::dvec4(t2.normal, glm::dot(t2.normal, t2.corners[0]));
  found.from = low.first;
  found.to = high.first;
  return found;
}

// The pieces of one seam between the same two planes (cut apart wherever
// a triangle edge of either part crosses it: a box's side through a wall
// in four or five) joined into one segment each, the largest turn of its
// pieces: fewer, longer lines for the crease pass to draw. Planes are
// matched to a millionth (a near miss joins nothing); pieces join where
// they touch or overlap along their line.
std::vector<FoundSeam> joined(std::vector<FoundSeam> pieces, double tolerance) {
  const auto grid = [](double v, double step) { return static_cast<std::int64_t>(std::llround(v / step)); };
  std::map<std::array<std::int64_t, 8>, std::vector<std::size_t>> by_planes;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const FoundSeam& p = pieces[i];
    by_planes[{grid(p.plane1.x, 1e-6), grid(p.plane1.y, 1e-6), grid(p.plane1.z, 1e-6), grid(p.plane1.w, 16 * tolerance),
               grid(p.plane2.x, 1e-6), grid(p.plane2.y, 1e-6), grid(p.plane2.z, 1e-6),
               grid(p.plane2.w, 16 * tolerance)}]
        .push_back(i);
  }
  std::vector<FoundSeam> seams;
  for (auto& [planes, group] : by_planes) {
    std::sort(group.begin(), group.end(),
              [&](std::size_t l, std::size_t r) { return pieces[l].from < pieces[r].from; });
    FoundSeam seam = pieces[group.front()];
    for (std::size_t k = 1; k < group.size(); ++k) {
      const FoundSeam& next = pieces[group[k]];
      if (next.from > seam.to + tolerance) {
        seams.push_back(seam);
        seam = next;
        continue;
      }
      if (next.to > seam.to) {
        seam.to = next.to;
        seam.points[2] = next.points[2];
      }
      seam.turn = std::max(seam.turn, next.turn);
    }
    seams.push_back(seam);
  }
  for (FoundSeam& seam : seams) seam.length = glm::distance(glm::dvec3(seam.points[1]), glm::dvec3(seam.points[2]));
  return seams;
}

// The pairs of triangles of different parts whose boxes overlap, through a
// tree of their boxes compared with itself: a node whose triangles are
// all of one part is not compared with itself, nor with a node of the same
// part.
class Search {
 public:
  Search(std::vector<Triangle> triangles, std::span<const glm::vec3> normals, std::span<const std::uint32_t> indices,
         double tolerance, const IntersectionSearch& options)
      : triangles_(std::move(triangles)),
        normals_(normals),
        indices_(indices),
        tolerance_(tolerance),
        options_(options),
        budget_(std::max(kLeastIntersectionWork,
                         static_cast<std::size_t>(options.work_per_triangle * static_cast<double>(triangles_.size())))),
        most_segments_(std::max(
            kLeastIntersectionSegments,
            static_cast<std::size_t>(options.segments_per_triangle * static_cast<double>(triangles_.size())))) {
    order_.resize(triangles_.size());
    std::iota(order_.begin(), order_.end(), 0u);
    if (!triangles_.empty()) build(0, static_cast<std::uint32_t>(triangles_.size()));
  }

  void run() {
    if (!nodes_.empty()) within(0);
  }
  bool gave_up() const { return gave_up_; }
  std::vector<FoundSeam>& found() { return found_; }

 private:
  std::uint32_t build(std::uint32_t first, std::uint32_t end) {
    const auto index = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
    SearchBox box, centres;
    for (std::uint32_t i = first; i < end; ++i) {
      const Triangle& t = triangles_[order_[i]];
      box.add(t.box);
      centres.add(0.5 * (t.box.min + t.box.max));
    }
    if (end - first <= kLeafTriangles) {
      std::uint32_t part = triangles_[order_[first]].part;
      for (std::uint32_t i = first; i < end; ++i) {
        if (triangles_[order_[i]].part != part) part = kMixedParts;
      }
      nodes_[index] = Node{box, first, end - first, 0, 0, part};
      return index;
    }
    const glm::dvec3 extent = centres.max - centres.min;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    const std::uint32_t middle = first + (end - first) / 2;
    std::nth_element(order_.begin() + first, order_.begin() + middle, order_.begin() + end,
                     [&](std::uint32_t l, std::uint32_t r) {
                       return triangles_[l].box.min[axis] + triangles_[l].box.max[axis] <
                              triangles_[r].box.min[axis] + triangles_[r].box.max[axis];
                     });
    const std::uint32_t left = build(first, middle);
    const std::uint32_t right = build(middle, end);
    const std::uint32_t part = nodes_[left].part == nodes_[right].part ? nodes_[left].part : kMixedParts;
    nodes_[index] = Node{box, 0, 0, left, right, part};
    return index;
  }

  // Counts one comparison; false once the search is to give up.
  bool spend() {
    if (gave_up_) return false;
    if (++work_ > budget_) {
      gave_up_ = true;
      return false;
    }
    if (work_ % kWorkBetweenTimeChecks == 1 && std::chrono::steady_clock::now() >= options_.deadline) {
      gave_up_ = true;
      return false;
    }
    return true;
  }

  void within(std::uint32_t n) {
    const Node node = nodes_[n];
    if (node.part != kMixedParts || gave_up_) return;
    if (node.count > 0) {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
        for (std::uint32_t j = i + 1; j < node.first + node.count; ++j) compare(order_[i], order_[j]);
      }
      return;
    }
    within(node.left);
    within(node.right);
    across(node.left, node.right);
  }

  void across(std::uint32_t a, std::uint32_t b) {
    const Node& na = nodes_[a];
    const Node& nb = nodes_[b];
    if ((na.part != kMixedParts && na.part == nb.part) || !na.box.overlaps(nb.box) || !spend()) return;
    if (na.count > 0 && nb.count > 0) {
      for (std::uint32_t i = na.first; i < na.first + na.count; ++i) {
        for (std::uint32_t j = nb.first; j < nb.first + nb.count; ++j) compare(order_[i], order_[j]);
      }
      return;
    }
    // Open the larger of the two (a leaf cannot be).
    if (nb.count > 0 || (na.count == 0 && na.box.size() >= nb.box.size())) {
      const std::uint32_t left = na.left, right = na.right;
      across(left, b);
      across(right, b);
    } else {
      const std::uint32_t left = nb.left, right = nb.right;
      across(a, left);
      across(a, right);
    }
  }

  void compare(std::uint32_t i, std::uint32_t j) {
    // The lower part first: a seam's pieces found from either side alike.
    if (triangles_[i].part > triangles_[j].part) std::swap(i, j);
    const Triangle& t1 = triangles_[i];
    const Triangle& t2 = triangles_[j];
    if (t1.part == t2.part || !t1.box.overlaps(t2.box) || !spend()) return;
    std::optional<FoundSeam> found = crossing(t1, t2, tolerance_);
    if (!found) return;
    const glm::dvec3 a(found->points[1]), b(found->points[2]);
    const double turn =
        std::max(turn_deg(shading_normal_at(a, t1, normals_, indices_), shading_normal_at(a, t2, normals_, indices_)),
                 turn_deg(shading_normal_at(b, t1, normals_, indices_), shading_normal_at(b, t2, normals_, indices_)));
    found->turn = static_cast<int>(std::min(std::ceil(turn), 180.0));
    if (found->turn <= kLeastTurnDeg) return;
    found_.push_back(*found);
    if (found_.size() > most_segments_) gave_up_ = true;
  }

  std::vector<Triangle> triangles_;
  std::span<const glm::vec3> normals_;
  std::span<const std::uint32_t> indices_;
  double tolerance_;
  const IntersectionSearch& options_;
  std::size_t budget_;
  std::size_t most_segments_;
  std::size_t work_ = 0;
  bool gave_up_ = false;
  std::vector<std::uint32_t> order_;
  std::vector<Node> nodes_;
  std::vector<FoundSeam> found_;
};

// The triangles that can cross anything (not degenerate), with their
// parts and boxes.
std::vector<Triangle> triangles_of(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
                                   std::span<const std::uint32_t> part_of_vertex, double tolerance) {
  std::vector<Triangle> triangles;
  triangles.reserve(indices.size() / 3);
  for (std::uint32_t i = 0; i + 2 < indices.size(); i += 3) {
    Triangle t;
    for (int k = 0; k < 3; ++k) t.corners[k] = glm::dvec3(positions[indices[i + k]]);
    if (is_degenerate_triangle(t.corners[0], t.corners[1], t.corners[2])) continue;
    t.normal = triangle_normal(t.corners[0], t.corners[1], t.corners[2]);
    if (t.normal == glm::dvec3(0.0)) continue;
    t.first_index = i;
    t.part = part_of_vertex[indices[i]];
    for (const glm::dvec3& c : t.corners) t.box.add(c);
    t.box.min -= glm::dvec3(tolerance);
    t.box.max += glm::dvec3(tolerance);
    triangles.push_back(t);
  }
  return triangles;
}

}  // namespace

std::vector<std::uint32_t> label_parts(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
                                       std::uint32_t& parts) {
  const std::vector<std::uint32_t> group = group_by_position(positions);
  const std::size_t groups = group.empty() ? 0 : *std::max_element(group.begin(), group.end()) + 1u;
  DisjointSets sets(groups);
  for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
    sets.join(group[indices[i]], group[indices[i + 1]]);
    sets.join(group[indices[i]], group[indices[i + 2]]);
  }
  constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> part_of_root(groups, kNone);
  parts = 0;
  for (const std::uint32_t index : indices) {
    std::uint32_t& part = part_of_root[sets.root(group[index])];
    if (part == kNone) part = parts++;
  }
  std::vector<std::uint32_t> part_of_vertex(positions.size(), kNone);
  for (std::size_t v = 0; v < positions.size(); ++v) part_of_vertex[v] = part_of_root[sets.root(group[v])];
  return part_of_vertex;
}

IntersectionLines find_intersection_lines(std::span<const glm::vec3> positions, std::span<const glm::vec3> normals,
                                          std::span<const std::uint32_t> indices,
                                          std::span<const std::uint32_t> part_of_vertex,
                                          const IntersectionSearch& options) {
  const Bounds bounds = compute_bounds(positions);
  const double diagonal = glm::length(glm::dvec3(bounds.max) - glm::dvec3(bounds.min));
  IntersectionLines lines;
  if (!(diagonal > 0.0)) return lines;
  const double tolerance = kTolerance * diagonal;
  Search search(triangles_of(positions, indices, part_of_vertex, tolerance), normals, indices, tolerance, options);
  search.run();
  if (search.gave_up()) {
    lines.complete = false;
    return lines;
  }
  std::vector<FoundSeam> found = joined(std::move(search.found()), tolerance);
  // The greatest turn first; within a turn, seams of one plane pair
  // together, and so mostly near one another.
  std::stable_sort(found.begin(), found.end(), [](const FoundSeam& l, const FoundSeam& r) { return l.turn > r.turn; });
  std::vector<int> turns;
  std::vector<double> lengths;
  lines.points.reserve(4 * found.size());
  for (const FoundSeam& f : found) {
    lines.points.insert(lines.points.end(), std::begin(f.points), std::end(f.points));
    turns.push_back(f.turn);
    lengths.push_back(f.length);
  }
  static_cast<TurnTally&>(lines) = tally_turns(turns, lengths, diagonal);
  return lines;
}

std::vector<IntersectionLines> find_intersection_lines(const Mesh& mesh, std::span<const glm::vec3> positions,
                                                       std::span<const glm::vec3> normals,
                                                       const IntersectionSearch& search) {
  std::uint32_t parts = 0;
  const std::vector<std::uint32_t> part_of_vertex = label_parts(mesh.positions, mesh.indices, parts);
  std::vector<IntersectionLines> levels(1 + mesh.lods.size());
  if (parts < 2) return levels;
  levels[0] = find_intersection_lines(positions, normals, mesh.indices, part_of_vertex, search);
  for (std::size_t i = 0; i < mesh.lods.size(); ++i) {
    if (!levels[0].complete) {
      levels[i + 1].complete = false;
      continue;
    }
    levels[i + 1] = find_intersection_lines(positions, normals, mesh.lods[i].indices, part_of_vertex, search);
  }
  return levels;
}

void find_intersection_lines(Mesh& mesh, const IntersectionSearch& search) {
  label_parts(mesh.positions, mesh.indices, mesh.parts);
  std::vector<IntersectionLines> levels = find_intersection_lines(mesh, mesh.positions, mesh.normals, search);
  mesh.intersections = std::move(levels[0]);
  for (std::size_t i = 0; i < mesh.lods.size(); ++i) mesh.lods[i].intersections = std::move(levels[i + 1]);
}

}  // namespace toond::scene
