#include "render/vector/line_candidates.h"

#include <cmath>
#include <unordered_map>

#include "render/vector/scene_seams.h"

namespace toond::render::vector {
namespace {

bool toward(Facing f) { return f == Facing::Toward; }

// The corner of triangle t at neither of an edge's two positions.
glm::dvec3 third_corner(const ViewMesh& mesh, std::uint32_t t, std::uint32_t ga, std::uint32_t gb) {
  for (int k = 0; k < 3; ++k) {
    const std::uint32_t p = mesh.corners[3 * t + k];
    if (mesh.groups[p] != ga && mesh.groups[p] != gb) return mesh.points[p];
  }
  return mesh.points[mesh.corners[3 * t]];
}

// The mesh edge between points pa and pb, joining and bordered where they are.
Segment edge_segment(const ViewMesh& mesh, std::uint32_t pa, std::uint32_t pb) {
  Segment s;
  s.a = mesh.points[pa];
  s.b = mesh.points[pb];
  s.node_a = s.group_a = mesh.groups[pa];
  s.node_b = s.group_b = mesh.groups[pb];
  return s;
}

// Mesh edges of one object: silhouettes and open edges.
void add_mesh_edges(const ViewMesh& mesh, const ViewObject& object, const LineChoice& choice,
                    std::vector<Segment>& out) {
  for (const MeshEdge& edge : object.edges->edges) {
    const std::uint32_t pa = object.first_vertex + edge.a;
    const std::uint32_t pb = object.first_vertex + edge.b;
    Segment s = edge_segment(mesh, pa, pb);
    const std::uint32_t f0 = object.first_triangle + edge.face0;
    if (edge.face1 == kNoFace) {
      if (!choice.boundaries) continue;
      s.kind = LineKind::Boundary;
      s.face = f0;
      s.surface_side = third_corner(mesh, f0, s.group_a, s.group_b);
    } else {
      // An edge-on face shows nothing of its front: it counts as turned
      // away, so an outline along it is not lost.
      const std::uint32_t f1 = object.first_triangle + edge.face1;
      const bool front0 = toward(mesh.facing[f0]);
      const bool front1 = toward(mesh.facing[f1]);
      if (!choice.silhouettes || front0 == front1) continue;
      s.kind = LineKind::Silhouette;
      s.face = front0 ? f0 : f1;
      s.surface_side = third_corner(mesh, s.face, s.group_a, s.group_b);
    }
    out.push_back(s);
  }
}

const scene::CreaseEdges& crease_edges_of(const scene::Mesh& mesh, std::size_t level) {
  return level == 0 ? mesh.crease_edges : mesh.lods[level - 1].crease_edges;
}

// Crease edges of one object whose faces turn alike.
void add_creases(const ViewMesh& mesh, const ViewObject& object, const LineChoice& choice, std::vector<Segment>& out) {
  const scene::CreaseEdges& creases = crease_edges_of(object.model->mesh, object.level);
  const std::size_t count = creases.creased_at(choice.crease_angle_deg);
  for (std::size_t e = 0; e < count; ++e) {
    const std::uint32_t* v = &creases.indices[4 * e];
    const glm::dvec3& c1 = mesh.points[object.first_vertex + v[0]];
    const std::uint32_t pa = object.first_vertex + v[1];
    const std::uint32_t pb = object.first_vertex + v[2];
    const glm::dvec3& c2 = mesh.points[object.first_vertex + v[3]];
    const Facing f1 = facing_of(mesh.points[pa], mesh.points[pb], c1, mesh.orthographic);
    const Facing f2 = facing_of(mesh.points[pb], mesh.points[pa], c2, mesh.orthographic);
    if (toward(f1) != toward(f2)) continue;  // a silhouette
    const bool hidden_whole = f1 == object.hidden_side && f2 == object.hidden_side;
    if (hidden_whole && !choice.keep_hidden) continue;
    Segment s = edge_segment(mesh, pa, pb);
    s.kind = LineKind::Crease;
    s.surely_hidden = hidden_whole;
    out.push_back(s);
  }
}

// Seam points shared by neighbouring segments, numbered as nodes: two
// segments' ends join where they agree to within the tolerance's grid.
class SeamNodes {
 public:
  SeamNodes(std::uint32_t first, double step) : next_(first), step_(step) {}
  std::uint32_t at(const glm::dvec3& p) {
    const Key key{std::llround(p.x / step_), std::llround(p.y / step_), std::llround(p.z / step_)};
    const auto [it, added] = ids_.try_emplace(key, next_);
    if (added) ++next_;
    return it->second;
  }
  std::uint32_t next() const { return next_; }

 private:
  struct Key {
    long long x, y, z;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      // Unsigned: wrapping is the mixing, not an overflow.
      const auto u = [](long long v) { return static_cast<std::uint64_t>(v); };
      return static_cast<std::size_t>((u(k.x) * 73856093u) ^ (u(k.y) * 19349663u) ^ (u(k.z) * 83492791u));
    }
  };
  std::unordered_map<Key, std::uint32_t, KeyHash> ids_;
  std::uint32_t next_;
  double step_;
};

const scene::IntersectionLines& seams_of(const ViewObject& object) {
  const scene::Mesh& mesh = object.model->mesh;
  if (object.pose && object.model->rig && object.level < object.pose->intersections.size()) {
    return object.pose->intersections[object.level];
  }
  return object.level == 0 ? mesh.intersections : mesh.lods[object.level - 1].intersections;
}

void add_seams(const ViewObject& object, const LineChoice& choice, SeamNodes& nodes, std::vector<Segment>& out) {
  const scene::IntersectionLines& seams = seams_of(object);
  const std::size_t count = seams.creased_at(choice.crease_angle_deg);
  for (std::size_t k = 0; k < count; ++k) {
    Segment s;
    s.a = glm::dvec3(object.to_view * glm::dvec4(glm::dvec3(seams.points[4 * k + 1]), 1.0));
    s.b = glm::dvec3(object.to_view * glm::dvec4(glm::dvec3(seams.points[4 * k + 2]), 1.0));
    s.node_a = nodes.at(s.a);
    s.node_b = nodes.at(s.b);
    s.kind = LineKind::Intersection;
    out.push_back(s);
  }
}

}  // namespace

Candidates line_candidates(const ViewMesh& mesh, const LineChoice& choice) {
  Candidates candidates;
  SeamNodes seam_nodes(mesh.group_count, mesh.tolerance);
  for (const ViewObject& object : mesh.objects) {
    if (choice.silhouettes || choice.boundaries) add_mesh_edges(mesh, object, choice, candidates.segments);
    if (choice.creases) add_creases(mesh, object, choice, candidates.segments);
    if (choice.intersections) add_seams(object, choice, seam_nodes, candidates.segments);
  }
  if (choice.intersections && mesh.objects.size() > 1) {
    for (const auto& [a, b] : scene_seams(mesh, choice.crease_angle_deg)) {
      Segment s;
      s.a = a;
      s.b = b;
      s.node_a = seam_nodes.at(a);
      s.node_b = seam_nodes.at(b);
      s.kind = LineKind::Intersection;
      candidates.segments.push_back(s);
    }
  }
  candidates.node_count = seam_nodes.next();
  return candidates;
}

}  // namespace toond::render::vector
