#include "scene/reading/mesh_builder.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

#include "scene/mesh/duplicate_triangles.h"
#include "scene/mesh/extreme_points.h"
#include "scene/mesh/flat_map.h"
#include "scene/mesh/mesh_processing.h"
#include "scene/mesh/normals_by_angle.h"
#include "scene/mesh/position_weld.h"
#include "scene/reading/import_error.h"

namespace toond::scene {

void ImportWarnings::add(std::string message) {
  // Messages quote the file's own names and text; the answer is JSON, so any
  // byte that would not make valid UTF-8 is shown as '?'.
  for (std::size_t i = 0; i < message.size();) {
    const auto c = static_cast<unsigned char>(message[i]);
    std::size_t extra = c < 0x80                          ? 0
                        : (c & 0xe0) == 0xc0 && c >= 0xc2 ? 1
                        : (c & 0xf0) == 0xe0              ? 2
                        : (c & 0xf8) == 0xf0 && c <= 0xf4 ? 3
                                                          : 99;
    bool ok = extra != 99 && i + extra < message.size();
    for (std::size_t k = 1; ok && k <= extra; ++k) ok = (static_cast<unsigned char>(message[i + k]) & 0xc0) == 0x80;
    if (c < 0x20 && c != '\t') ok = false;
    if (!ok) {
      message[i++] = '?';
      continue;
    }
    i += extra + 1;
  }
  if (message.size() > kMaxMessageBytes) {
    // Cut at a character boundary (the text is valid UTF-8 by now).
    std::size_t cut = kMaxMessageBytes;
    while (cut > 0 && (static_cast<unsigned char>(message[cut]) & 0xc0) == 0x80) --cut;
    message.resize(cut);
    message += "…";
  }
  const auto [it, inserted] = seen_.try_emplace(message, kDropped);
  if (!inserted) {
    if (it->second != kDropped)
      ++counts_[it->second];
    else
      ++dropped_;
    return;
  }
  if (list_.size() < kMaxWarnings) {
    it->second = list_.size();
    list_.push_back(std::move(message));
    counts_.push_back(1);
  } else {
    ++dropped_;
  }
}

void ImportWarnings::add_summary(std::string message) {
  ImportWarnings one;
  one.add(std::move(message));
  for (std::string& m : one.take()) summaries_.push_back(std::move(m));
}

std::vector<std::string> ImportWarnings::take() {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < list_.size(); ++i) {
    out.push_back(counts_[i] > 1 ? std::to_string(counts_[i]) + " × " + list_[i] : std::move(list_[i]));
  }
  for (std::string& m : summaries_) out.push_back(std::move(m));
  summaries_.clear();
  if (dropped_ > 0) out.push_back(std::to_string(dropped_) + " further warnings left out");
  list_.clear();
  counts_.clear();
  seen_.clear();
  dropped_ = 0;
  return out;
}

namespace {

struct VertexKey {
  std::uint32_t v;
  std::int64_t vn;
  std::int64_t vt;
  std::int64_t tangent;
  std::int64_t smoothing;
  bool operator==(const VertexKey&) const = default;
};

struct VertexKeyHash {
  std::size_t operator()(const VertexKey& k) const noexcept {
    std::uint64_t h = 1469598103934665603ull;
    for (const std::uint64_t part :
         {static_cast<std::uint64_t>(k.v), static_cast<std::uint64_t>(k.vn), static_cast<std::uint64_t>(k.vt),
          static_cast<std::uint64_t>(k.tangent), static_cast<std::uint64_t>(k.smoothing)}) {
      h = (h ^ part) * 1099511628211ull;
    }
    return static_cast<std::size_t>(h);
  }
};

struct GroupKey {
  std::uint32_t position;
  std::int64_t smoothing;
  bool operator==(const GroupKey&) const = default;
};

// The smoothing of a vertex whose normal is averaged over a corner group
// made by angle (GroupKey::position then holds the group).
constexpr std::int64_t kAngleGroup = std::numeric_limits<std::int64_t>::min() + 1;

struct GroupKeyHash {
  std::size_t operator()(const GroupKey& k) const noexcept {
    return std::hash<std::uint64_t>()((static_cast<std::uint64_t>(k.position) << 20) ^
                                      static_cast<std::uint64_t>(k.smoothing));
  }
};

std::string plural(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

class Builder {
 public:
  Builder(MeshSource& source, ImportWarnings& warnings) : src_(source), warnings_(warnings) {}

  Mesh run(const std::function<void(std::vector<SourceTriangle>&)>& assign_materials) {
    check_limits();
    if (src_.z_up) turn_z_up();
    check_positions();
    check_indices();
    sanitize_colors();
    recentre();
    drop_degenerate();
    if (src_.triangles.empty()) {
      throw ImportError(src_.file, src_.file +
                                       " has no faces to render (it holds only points, lines or "
                                       "degenerate faces, or nothing at all)");
    }
    assign_materials(src_.triangles);
    const auto by_material = [](const SourceTriangle& a, const SourceTriangle& b) { return a.material < b.material; };
    // Most files are sorted already (one material, or a run per material),
    // and a stable sort moves every triangle of a sorted list all the same.
    if (!std::is_sorted(src_.triangles.begin(), src_.triangles.end(), by_material)) {
      std::stable_sort(src_.triangles.begin(), src_.triangles.end(), by_material);
    }
    drop_repeated();
    build();
    return std::move(mesh_);
  }

 private:
  std::string describe_position(std::size_t i) const {
    return src_.describe_position ? src_.describe_position(i) : "vertex " + std::to_string(i + 1);
  }

  void check_limits() const {
    if (src_.positions.size() > src_.limits.max_vertices) {
      throw ImportLimitError(
          src_.file, ImportLimit::Vertices, static_cast<double>(src_.limits.max_vertices),
          src_.file + " has " + std::to_string(src_.positions.size()) + " vertex positions, more than");
    }
    if (src_.triangles.size() > src_.limits.max_triangles) {
      throw ImportLimitError(src_.file, ImportLimit::Triangles, static_cast<double>(src_.limits.max_triangles),
                             src_.file + " has " + std::to_string(src_.triangles.size()) + " triangles, more than");
    }
  }

  // A quarter turn about +X (up_axis_turn), applied to every direction the
  // file gives too.
  void turn_z_up() {
    const glm::dmat3 turn = up_axis_turn(true);
    for (glm::dvec3& p : src_.positions) p = turn * p;
    for (glm::dvec3& n : src_.normals) n = turn * n;
    for (glm::dvec4& t : src_.tangents) t = glm::dvec4(turn * glm::dvec3(t), t.w);
  }

  void check_positions() const {
    for (std::size_t i = 0; i < src_.positions.size(); ++i) {
      const glm::dvec3& p = src_.positions[i];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
        throw ImportError(src_.file,
                          src_.file + ": " + describe_position(i) + " has a coordinate that is not a finite number");
      }
    }
  }

  void check_indices() {
    const auto normal_count = static_cast<std::int64_t>(src_.normals.size());
    const auto texcoord_count = static_cast<std::int64_t>(src_.texcoords.size());
    const auto tangent_count = static_cast<std::int64_t>(src_.tangents.size());
    std::size_t dropped = 0;
    for (std::size_t t = 0; t < src_.triangles.size(); ++t) {
      for (SourceCorner& corner : src_.triangles[t].corner) {
        if (corner.position >= src_.positions.size()) {
          throw ImportError(src_.file, src_.file + ": triangle " + std::to_string(t + 1) +
                                           " refers to a vertex position that does not exist (the file defines " +
                                           std::to_string(src_.positions.size()) + ")");
        }
        if (corner.normal < -1 || corner.normal >= normal_count) {
          corner.normal = -1;
          ++dropped;
        }
        if (corner.texcoord < -1 || corner.texcoord >= texcoord_count) {
          corner.texcoord = -1;
          ++dropped;
        }
        if (corner.tangent < -1 || corner.tangent >= tangent_count) {
          corner.tangent = -1;
          ++dropped;
        }
      }
    }
    if (dropped > 0) {
      warnings_.add(src_.file + ": " + std::to_string(dropped) +
                    " normal, texture-coordinate or tangent references point past the end of their lists and were "
                    "ignored");
    }
  }

  // A vertex whose corner came with a usable tangent (finite, of some
  // length, a handedness) keeps it: the file's normal map was baked against
  // it. The rest keep the derived one.
  void keep_file_tangents(Mesh& mesh, const std::vector<std::int64_t>& file_tangents) const {
    for (std::size_t v = 0; v < file_tangents.size(); ++v) {
      if (file_tangents[v] < 0) continue;
      const glm::dvec4 t = src_.tangents[static_cast<std::size_t>(file_tangents[v])];
      const glm::dvec3 along(t);
      const double length = glm::length(along);
      if (!std::isfinite(length) || !(length > 1e-12) || !std::isfinite(t.w) || t.w == 0.0) continue;
      mesh.tangents[v] = glm::vec4(glm::vec3(along / length), t.w < 0.0 ? -1.0f : 1.0f);
    }
  }

  void sanitize_colors() {
    auto& colors = src_.colors;
    if (colors.empty()) return;
    if (colors.size() != src_.positions.size()) {
      warnings_.add(src_.file + ": not every vertex has a colour; the vertex colours were ignored");
      colors.clear();
      return;
    }
    std::size_t not_finite = 0;
    double highest = 0.0;
    double lowest = 0.0;
    bool all_whole = true;
    for (auto& c : colors) {
      for (int k = 0; k < 3; ++k) {
        if (!std::isfinite(c[k])) {
          c[k] = 1.0;
          ++not_finite;
        }
        highest = std::max(highest, c[k]);
        lowest = std::min(lowest, c[k]);
        all_whole = all_whole && c[k] == std::floor(c[k]);
      }
    }
    if (not_finite > 0) {
      warnings_.add(src_.file + ": " +
                    plural(not_finite, "vertex colour component was", "vertex colour components were") +
                    " not a finite number and became 1");
    }
    if (highest > 1.0 && highest <= 255.0 && all_whole && lowest >= 0.0) {
      // Some exporters write bytes; dividing keeps the picture.
      for (auto& c : colors) c /= 255.0;
      warnings_.add(src_.file + ": the vertex colours are whole numbers up to 255 and were read as 0..255");
    } else if (highest > 1.0 || lowest < 0.0) {
      for (auto& c : colors) c = glm::clamp(c, 0.0, 1.0);
      warnings_.add(src_.file + ": vertex colours outside 0..1 were clamped");
    }
  }

  void recentre() {
    if (src_.triangles.empty()) return;
    // The centre is taken in double from the file's own numbers, so that a
    // model far from its origin keeps full float precision once recentred.
    glm::dvec3 lo(std::numeric_limits<double>::infinity());
    glm::dvec3 hi(-std::numeric_limits<double>::infinity());
    for (const auto& tri : src_.triangles) {
      for (const auto& corner : tri.corner) {
        lo = glm::min(lo, src_.positions[corner.position]);
        hi = glm::max(hi, src_.positions[corner.position]);
      }
    }
    origin_ = (lo + hi) * 0.5;
    const glm::dvec3 extent = hi - lo;
    if (!std::isfinite(extent.x) || !std::isfinite(extent.y) || !std::isfinite(extent.z) ||
        std::max({extent.x, extent.y, extent.z}) > static_cast<double>(std::numeric_limits<float>::max()) * 0.5) {
      throw ImportError(src_.file, src_.file + ": the model's extent is too large to render");
    }
  }

  glm::dvec3 position(std::uint32_t v) const { return src_.positions[v] - origin_; }

  void drop_degenerate() {
    std::size_t degenerate = 0;
    std::size_t kept = 0;
    for (std::size_t t = 0; t < src_.triangles.size(); ++t) {
      const SourceTriangle& tri = src_.triangles[t];
      glm::dvec3 exact[3];
      glm::dvec3 rounded[3];
      for (int c = 0; c < 3; ++c) {
        exact[c] = position(tri.corner[c].position);
        rounded[c] = glm::dvec3(glm::vec3(exact[c]));
      }
      // The GPU sees the float corners: a face that collapses there is as
      // degenerate as one that is flat in the file.
      if (is_degenerate_triangle(exact[0], exact[1], exact[2]) ||
          is_degenerate_triangle(rounded[0], rounded[1], rounded[2])) {
        ++degenerate;
        continue;
      }
      src_.triangles[kept++] = tri;
    }
    src_.triangles.resize(kept);
    if (degenerate > 0) {
      warnings_.add_summary(
          src_.file + ": " +
          plural(degenerate, "degenerate (zero-area) triangle was", "degenerate (zero-area) triangles were") +
          " dropped");
    }
  }

  // After the sort by material, so that of a face repeated under several
  // materials the one kept is the one drawn last, which is what the main
  // pass's less-or-equal depth test shows.
  void drop_repeated() {
    std::vector<TriangleCorners> corners(src_.triangles.size());
    for (std::size_t t = 0; t < corners.size(); ++t) {
      for (int c = 0; c < 3; ++c) corners[t].corner[c] = src_.positions[src_.triangles[t].corner[c].position];
    }
    const std::vector<bool> keep = last_of_each_triangle(corners);
    std::size_t kept = 0;
    for (std::size_t t = 0; t < keep.size(); ++t) {
      if (keep[t]) src_.triangles[kept++] = src_.triangles[t];
    }
    const std::size_t repeated = src_.triangles.size() - kept;
    src_.triangles.resize(kept);
    if (repeated > 0) {
      warnings_.add_summary(src_.file + ": " + plural(repeated, "triangle repeated", "triangles repeated") +
                            " the corners of another and " + (repeated == 1 ? "was" : "were") +
                            " dropped (of each face the one drawn last is kept)");
    }
  }

  bool normal_usable(std::int64_t vn) const {
    if (vn < 0) return false;
    const double len = glm::length(src_.normals[static_cast<std::size_t>(vn)]);
    return std::isfinite(len) && len > 1e-20;
  }

  // Smoothing off: corners share a vertex only with faces lying in the same
  // plane (the triangles of one polygon), keyed by the face normal's bits.
  // Negative, so it never meets a smoothing group's key.
  std::int64_t flat_key(const SourceTriangle& tri) const {
    const glm::vec3 n(triangle_normal(position(tri.corner[0].position), position(tri.corner[1].position),
                                      position(tri.corner[2].position)));
    std::uint32_t bits[3];
    std::memcpy(bits, &n[0], sizeof bits);
    std::uint64_t h = 1469598103934665603ull;
    for (const auto b : bits) h = (h ^ b) * 1099511628211ull;
    return -1 - static_cast<std::int64_t>(h >> 2);
  }

  // Normals by angle (scene/mesh/normals_by_angle.h): corners of one vertex
  // whose faces meet at a sharp edge around it get a vertex each, a copy of
  // the first; returns per vertex (copies included) its corner group, which
  // its normal is averaged over.
  std::vector<std::uint32_t> split_by_angle(std::vector<std::uint32_t>& position_class, std::vector<bool>& needs_normal,
                                            std::vector<std::int64_t>& smoothing_of_vertex,
                                            std::vector<std::int64_t>& file_tangents) {
    Mesh& mesh = mesh_;
    std::vector<std::uint8_t> eligible(mesh.indices.size());
    for (std::size_t c = 0; c < eligible.size(); ++c) eligible[c] = needs_normal[mesh.indices[c]];
    const std::vector<std::uint32_t> corner_group =
        corner_groups_by_angle(mesh.positions, position_class, mesh.indices, eligible, src_.smooth_angle_deg);
    constexpr std::uint32_t kNone = ~0u;
    std::vector<std::uint32_t> group_of_vertex(mesh.positions.size(), kNone);
    // The copy of vertex v for corner group g. A corner group nearly always
    // lies on one vertex, so the group keeps its first copy, and the map is
    // asked only for a group over several vertices at one point (a seam's).
    const std::size_t corner_groups =
        corner_group.empty() ? 0 : *std::max_element(corner_group.begin(), corner_group.end()) + std::size_t{1};
    std::vector<std::uint32_t> first_copied(corner_groups, kNone);  // by corner group: the vertex
    std::vector<std::uint32_t> first_copy(corner_groups, kNone);    // and its copy
    FlatMap<std::uint64_t, std::uint32_t, std::hash<std::uint64_t>> more_copies;
    const auto copy_of = [&](std::uint32_t v, std::uint32_t g) -> std::pair<std::uint32_t, bool> {
      const auto next = static_cast<std::uint32_t>(mesh.positions.size());
      if (first_copied[g] == kNone) {
        first_copied[g] = v;
        first_copy[g] = next;
        return {next, true};
      }
      if (first_copied[g] == v) return {first_copy[g], false};
      const auto [copy, added] = more_copies.try_emplace((static_cast<std::uint64_t>(v) << 32) | g, next);
      return {copy, added};
    };
    for (std::size_t c = 0; c < mesh.indices.size(); ++c) {
      if (!eligible[c]) continue;
      const std::uint32_t v = mesh.indices[c];
      const std::uint32_t g = corner_group[c];
      if (group_of_vertex[v] == kNone) group_of_vertex[v] = g;
      if (group_of_vertex[v] == g) continue;
      const auto [copy, inserted] = copy_of(v, g);
      if (inserted) {
        mesh.positions.push_back(mesh.positions[v]);
        mesh.normals.push_back(mesh.normals[v]);
        mesh.texcoords.push_back(mesh.texcoords[v]);
        if (!mesh.colors.empty()) mesh.colors.push_back(mesh.colors[v]);
        if (!mesh.motion.empty()) mesh.motion.push_back(mesh.motion[v]);
        file_tangents.push_back(file_tangents[v]);
        smoothing_of_vertex.push_back(smoothing_of_vertex[v]);
        needs_normal.push_back(true);
        position_class.push_back(position_class[v]);
        group_of_vertex.push_back(g);
      }
      mesh.indices[c] = copy;
    }
    return group_of_vertex;
  }

  // The groups computed normals are averaged over, numbered in order of
  // first appearance. A vertex that brought its own normal forms a group of
  // its own (its computed normal is discarded anyway); the rest group by
  // position and smoothing group, or (groups_by_angle) by the corner group
  // normals by angle gave them.
  static std::vector<std::uint32_t> groups_by_smoothing(const std::vector<std::uint32_t>& position_class,
                                                        const std::vector<bool>& needs_normal,
                                                        const std::vector<std::int64_t>& smoothing_of_vertex) {
    FlatMap<GroupKey, std::uint32_t, GroupKeyHash> group_ids(needs_normal.size());
    std::vector<std::uint32_t> groups(needs_normal.size());
    for (std::size_t v = 0; v < groups.size(); ++v) {
      const GroupKey key = !needs_normal[v]
                               ? GroupKey{static_cast<std::uint32_t>(v), std::numeric_limits<std::int64_t>::min()}
                               : GroupKey{position_class[v], smoothing_of_vertex[v]};
      groups[v] = group_ids.try_emplace(key, static_cast<std::uint32_t>(group_ids.size())).first;
    }
    return groups;
  }

  // Corner groups are dense numbers, so they are renumbered through an
  // array rather than a map.
  static std::vector<std::uint32_t> groups_by_angle(const std::vector<std::uint32_t>& angle_group,
                                                    const std::vector<bool>& needs_normal) {
    constexpr std::uint32_t kNone = ~0u;
    std::uint32_t highest = 0;
    for (const std::uint32_t g : angle_group) {
      if (g != kNone) highest = std::max(highest, g);
    }
    std::vector<std::uint32_t> id_of(std::size_t{highest} + 2, kNone);  // by corner group; the last for none
    std::vector<std::uint32_t> groups(needs_normal.size());
    std::uint32_t next = 0;
    for (std::size_t v = 0; v < groups.size(); ++v) {
      if (!needs_normal[v]) {
        groups[v] = next++;
        continue;
      }
      std::uint32_t& id = id_of[angle_group[v] == kNone ? id_of.size() - 1 : angle_group[v]];
      if (id == kNone) id = next++;
      groups[v] = id;
    }
    return groups;
  }

  // What the vertices were made of, for the steps after them.
  struct VertexOrigins {
    bool smoothing_in_use = false;
    std::vector<std::int64_t> smoothing;      // per vertex: where its computed normal may average
    std::vector<bool> needs_normal;           // per vertex: the source gave none usable
    std::vector<std::int64_t> file_tangents;  // per vertex: its corner's tangent in the source, or -1
  };

  void build() {
    mesh_.origin = origin_;
    VertexOrigins origins = make_vertices();
    check_import_time(src_.limits, "building vertices");
    const WeldReport weld = weld_positions(mesh_.positions);
    mesh_.weld_tolerance = weld.tolerance;
    mesh_.welded_positions = weld.moved;
    // Which vertices lie at one point, for every step below; split copies
    // made for normals by angle join their original's class.
    std::vector<std::uint32_t> position_class = group_by_position(mesh_.positions);
    fill_missing_normals(origins, position_class);
    check_import_time(src_.limits, "computing normals");
    mesh_.outline_normals = compute_outline_normals(mesh_.positions, mesh_.indices, mesh_.normals, position_class);
    check_import_time(src_.limits, "computing outline normals");
    measure(origins.file_tangents, position_class);
    check_import_time(src_.limits, "measuring the mesh");
    cut_submeshes();
  }

  bool smoothing_groups_in_use() const {
    for (const auto& tri : src_.triangles) {
      for (const auto& corner : tri.corner) {
        if (tri.smoothing != 0 && !normal_usable(corner.normal)) return true;
      }
    }
    return false;
  }

  // Vertices without a usable normal are told apart by where their
  // computed normal may average: the whole mesh, one smoothing group, or
  // (smoothing off) only their own face.
  std::int64_t smoothing_key(const SourceTriangle& tri, bool has_normal, bool smoothing_in_use) const {
    if (has_normal) return 0;
    if (!smoothing_in_use) return 1;
    if (tri.smoothing != 0) return 2 + static_cast<std::int64_t>(tri.smoothing);
    return flat_key(tri);
  }

  // One vertex per distinct corner (position, normal, texture coordinate,
  // tangent, smoothing), and the indices of every triangle's corners.
  VertexOrigins make_vertices() {
    VertexOrigins origins;
    origins.smoothing_in_use = smoothing_groups_in_use();
    const auto& triangles = src_.triangles;
    FlatMap<VertexKey, std::uint32_t, VertexKeyHash> vertex_of(triangles.size());
    std::size_t bad_texcoords = 0;
    mesh_.indices.reserve(triangles.size() * 3);
    for (const auto& tri : triangles) {
      for (const auto& corner : tri.corner) {
        const bool has_normal = normal_usable(corner.normal);
        const std::int64_t smoothing = smoothing_key(tri, has_normal, origins.smoothing_in_use);
        const VertexKey key{corner.position, has_normal ? corner.normal : -1, corner.texcoord, corner.tangent,
                            smoothing};
        const auto [vertex, inserted] = vertex_of.try_emplace(key, static_cast<std::uint32_t>(mesh_.positions.size()));
        if (inserted) {
          bad_texcoords += add_vertex(corner, has_normal) ? 0 : 1;
          origins.file_tangents.push_back(corner.tangent);
          origins.smoothing.push_back(smoothing);
          origins.needs_normal.push_back(!has_normal);
        }
        mesh_.indices.push_back(vertex);
      }
    }
    if (bad_texcoords > 0) {
      warnings_.add(src_.file + ": " + std::to_string(bad_texcoords) +
                    " texture coordinates were not finite numbers and were set to 0");
    }
    return origins;
  }

  // The vertex of `corner`; false where its texture coordinate was no
  // finite number (and is 0).
  bool add_vertex(const SourceCorner& corner, bool has_normal) {
    if (mesh_.positions.size() >= std::numeric_limits<std::uint32_t>::max()) {
      throw ImportError(src_.file, src_.file + " has too many vertices");
    }
    mesh_.positions.emplace_back(position(corner.position));
    glm::vec3 normal(0.0f);
    if (has_normal) normal = glm::vec3(glm::normalize(src_.normals[static_cast<std::size_t>(corner.normal)]));
    mesh_.normals.push_back(normal);
    glm::vec2 uv(0.0f);
    bool finite = true;
    if (corner.texcoord >= 0) {
      const glm::dvec2 raw = src_.texcoords[static_cast<std::size_t>(corner.texcoord)];
      finite = std::isfinite(raw.x) && std::isfinite(raw.y) && std::abs(raw.x) < 1e30 && std::abs(raw.y) < 1e30;
      if (finite) uv = glm::vec2(raw);
    }
    mesh_.texcoords.push_back(uv);
    if (!src_.colors.empty()) mesh_.colors.emplace_back(src_.colors[corner.position]);
    if (!src_.motions.empty()) mesh_.motion.push_back(src_.motions[corner.position]);
    return finite;
  }

  // Normals for the vertices the source gave none: by smoothing group, or,
  // without smoothing groups, by the angle between faces (which adds a
  // copy of a vertex, to `origins` and `position_class` too, for each
  // corner group past its first).
  void fill_missing_normals(VertexOrigins& origins, std::vector<std::uint32_t>& position_class) {
    const std::vector<bool>& needs_normal = origins.needs_normal;
    if (std::find(needs_normal.begin(), needs_normal.end(), true) == needs_normal.end()) return;
    const std::vector<std::uint32_t> angle_group =
        origins.smoothing_in_use
            ? std::vector<std::uint32_t>{}
            : split_by_angle(position_class, origins.needs_normal, origins.smoothing, origins.file_tangents);
    const std::vector<std::uint32_t> groups = angle_group.empty()
                                                  ? groups_by_smoothing(position_class, needs_normal, origins.smoothing)
                                                  : groups_by_angle(angle_group, needs_normal);
    const auto computed = compute_grouped_normals(mesh_.positions, mesh_.indices, groups);
    for (std::size_t v = 0; v < groups.size(); ++v) {
      if (needs_normal[v]) mesh_.normals[v] = computed[v];
    }
  }

  // Tangents, bounds, extreme points, creases and the cost profile.
  void measure(const std::vector<std::int64_t>& file_tangents, const std::vector<std::uint32_t>& position_class) {
    Mesh& mesh = mesh_;
    mesh.tangents = compute_tangents(mesh.positions, mesh.normals, mesh.texcoords, mesh.indices);
    keep_file_tangents(mesh, file_tangents);
    mesh.bounds = compute_bounds(mesh.positions);
    mesh.extremes = extreme_points(mesh.positions, position_class);
    mesh.creases = measure_creases(mesh.positions, mesh.normals, mesh.indices, position_class);
    mesh.cost = measure_render_cost(mesh.positions, mesh.indices, mesh.bounds.max - mesh.bounds.min);
  }

  // A submesh per run of triangles of one material.
  void cut_submeshes() {
    const auto& triangles = src_.triangles;
    for (std::size_t t = 0; t < triangles.size();) {
      Submesh sub;
      sub.material = triangles[t].material;
      sub.first_index = static_cast<std::uint32_t>(t * 3);
      std::size_t end = t;
      while (end < triangles.size() && triangles[end].material == sub.material) ++end;
      sub.index_count = static_cast<std::uint32_t>((end - t) * 3);
      mesh_.submeshes.push_back(sub);
      t = end;
    }
  }

  MeshSource& src_;
  ImportWarnings& warnings_;
  glm::dvec3 origin_{0.0};
  Mesh mesh_;
};

}  // namespace

Model build_single_material_model(MeshSource& source, ImportWarnings& warnings) {
  Model model;
  model.mesh = build_mesh(source, warnings, [](std::vector<SourceTriangle>& triangles) {
    for (SourceTriangle& tri : triangles) tri.material = 0;
  });
  model.has_vertex_colors = !model.mesh.colors.empty();
  Material material;
  material.name = "default";
  material.diffuse = glm::vec3(model.has_vertex_colors ? 1.0f : 0.8f);
  model.materials.push_back(std::move(material));
  model.warnings = warnings.take();
  return model;
}

glm::dmat3 up_axis_turn(bool z_up) {
  if (!z_up) return glm::dmat3(1.0);
  // Columns: where +X, +Y and +Z go.
  return glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, 0, -1), glm::dvec3(0, 1, 0));
}

void apply_import_choices(MeshSource& source, const ImportChoices& choices) {
  source.smooth_angle_deg = choices.smooth_angle.value_or(kDefaultSmoothAngle);
  source.z_up = choices.z_up();
}

Mesh build_mesh(MeshSource& source, ImportWarnings& warnings,
                const std::function<void(std::vector<SourceTriangle>&)>& assign_materials) {
  return Builder(source, warnings).run(assign_materials);
}

}  // namespace toond::scene
