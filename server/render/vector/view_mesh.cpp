#include "render/vector/view_mesh.h"

#include <stdexcept>

#include "render/vector/parallel_runs.h"
#include "scene/animation/pose.h"

namespace toond::render::vector {
namespace {

constexpr std::size_t kVerticesPerRun = 16384;

// The object's vertices where its pose puts them (posed on the CPU by the
// pipeline); its own when it is not posed.
std::span<const glm::vec3> positions_of(const PlannedObject& object, std::vector<glm::vec3>& posed) {
  const scene::Mesh& mesh = object.model.mesh;
  if (object.pose == nullptr || object.model.rig == nullptr) return mesh.positions;
  if (!object.pose->cpu_sums) throw std::logic_error("a line drawing needs its poses' vertices posed on the CPU");
  posed.resize(mesh.positions.size());
  const scene::PoseSums& sums = *object.pose->cpu_sums;
  for_each_run(posed.size(), kVerticesPerRun, [&](std::size_t, std::size_t first, std::size_t end) {
    for (std::size_t v = first; v < end; ++v)
      posed[v] = scene::pose_vertex(mesh, *object.model.rig, sums, v, false).position;
  });
  return posed;
}

const std::vector<std::uint32_t>& level_indices(const scene::Mesh& mesh, std::size_t level) {
  return level == 0 ? mesh.indices : mesh.lods[level - 1].indices;
}

Facing side_of(HiddenFaces hidden) {
  switch (hidden) {
    case HiddenFaces::None:
      return Facing::EdgeOn;
    case HiddenFaces::Back:
      return Facing::Away;
    case HiddenFaces::Front:
      return Facing::Toward;
  }
  return Facing::EdgeOn;
}

// Object i's vertices and triangles appended to `mesh`.
void add_object(const FramePlan& plan, std::span<const PlannedObject> objects, std::size_t i,
                std::shared_ptr<const ModelEdges> edges, ViewMesh& mesh) {
  const PlannedObject& object = objects[i];
  ViewObject view;
  view.first_vertex = static_cast<std::uint32_t>(mesh.points.size());
  view.first_triangle = static_cast<std::uint32_t>(mesh.triangle_count());
  view.group_offset = mesh.group_count;
  view.level = plan.objects[i].lod.level;
  view.model = &object.model;
  view.pose = object.pose;
  view.edges = std::move(edges);
  view.to_view = plan.camera.view * plan.scene->matrices[i];
  const FaceSkip& skip = plan.objects[i].main;
  if (!skip.unless_caps_show) view.hidden_side = side_of(skip.hidden);
  std::vector<glm::vec3> posed;
  const std::span<const glm::vec3> positions = positions_of(object, posed);
  mesh.points.resize(view.first_vertex + positions.size());
  for_each_run(positions.size(), kVerticesPerRun, [&](std::size_t, std::size_t first, std::size_t end) {
    for (std::size_t v = first; v < end; ++v) {
      mesh.points[view.first_vertex + v] = glm::dvec3(view.to_view * glm::dvec4(glm::dvec3(positions[v]), 1.0));
    }
  });
  mesh.groups.reserve(mesh.groups.size() + view.edges->group.size());
  for (std::uint32_t g : view.edges->group) mesh.groups.push_back(view.group_offset + g);
  mesh.group_count += view.edges->group_count;
  const std::vector<std::uint32_t>& indices = level_indices(object.model.mesh, view.level);
  mesh.corners.reserve(mesh.corners.size() + indices.size());
  for (std::uint32_t index : indices) mesh.corners.push_back(view.first_vertex + index);
  view.triangle_count = static_cast<std::uint32_t>(indices.size() / 3);
  mesh.objects.push_back(std::move(view));
}

// Every triangle's facing, and whether it may hide anything: not where it
// lies on its closed object's hidden side, nor edge-on.
void face_triangles(ViewMesh& mesh) {
  mesh.facing.resize(mesh.triangle_count());
  mesh.hides.resize(mesh.triangle_count());
  for (const ViewObject& object : mesh.objects) {
    for_each_run(object.triangle_count, kVerticesPerRun, [&](std::size_t, std::size_t first, std::size_t end) {
      for (std::size_t t = object.first_triangle + first; t < object.first_triangle + end; ++t) {
        const Facing f = facing_of(mesh.corner(t, 0), mesh.corner(t, 1), mesh.corner(t, 2), mesh.orthographic);
        mesh.facing[t] = f;
        mesh.hides[t] = f != Facing::EdgeOn && f != object.hidden_side;
      }
    });
  }
}

// The side of triangle t (0: corners 0 to 1, 1: 1 to 2, 2: 2 to 0) between
// the welded positions ga and gb.
int side_between(const ViewMesh& mesh, std::uint32_t t, std::uint32_t ga, std::uint32_t gb) {
  for (int k = 0; k < 3; ++k) {
    const std::uint32_t g0 = mesh.groups[mesh.corners[3 * t + k]];
    const std::uint32_t g1 = mesh.groups[mesh.corners[3 * t + (k + 1) % 3]];
    if ((g0 == ga && g1 == gb) || (g0 == gb && g1 == ga)) return k;
  }
  return -1;
}

// Marks the sides two hiding triangles share.
void mark_shared_sides(ViewMesh& mesh) {
  mesh.shared_sides.assign(mesh.triangle_count(), 0);
  for (const ViewObject& object : mesh.objects) {
    for (const MeshEdge& edge : object.edges->edges) {
      if (edge.face1 == kNoFace) continue;
      const std::uint32_t f0 = object.first_triangle + edge.face0, f1 = object.first_triangle + edge.face1;
      if (!mesh.hides[f0] || !mesh.hides[f1]) continue;
      const std::uint32_t ga = mesh.groups[object.first_vertex + edge.a];
      const std::uint32_t gb = mesh.groups[object.first_vertex + edge.b];
      for (std::uint32_t f : {f0, f1}) {
        const int k = side_between(mesh, f, ga, gb);
        if (k >= 0) mesh.shared_sides[f] |= static_cast<std::uint8_t>(1u << k);
      }
    }
  }
}

}  // namespace

Facing facing_of(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, bool orthographic) {
  const glm::dvec3 n = glm::cross(b - a, c - a);
  // Toward the eye: at the origin, or along +z in an orthographic view.
  const double toward = orthographic ? n.z : -glm::dot(n, a);
  const double scale = glm::length(n) * (orthographic ? 1.0 : glm::length(a));
  if (!(std::abs(toward) > 1e-12 * scale)) return Facing::EdgeOn;
  return toward > 0 ? Facing::Toward : Facing::Away;
}

ViewMesh view_mesh_of(const FramePlan& plan, std::span<const PlannedObject> objects,
                      std::span<const std::shared_ptr<const scene::Model>> models, EdgeCache& edges) {
  ViewMesh mesh;
  mesh.orthographic = plan.viewer.orthographic;
  mesh.tolerance = 1e-6 * std::max(static_cast<double>(plan.scene->bounds.radius()), 1e-300);
  for (std::size_t i = 0; i < objects.size(); ++i)
    add_object(plan, objects, i, edges.get(models[i], plan.objects[i].lod.level), mesh);
  face_triangles(mesh);
  mark_shared_sides(mesh);
  return mesh;
}

}  // namespace toond::render::vector
