#pragma once
// What every importer does once its parser has read a file: the checks,
// recentring, repairs and derived vertex streams that turn the file's
// indexed lists into a Mesh. The OBJ and .m importers fill a MeshSource and
// call build_mesh, so both models get exactly the same treatment.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <unordered_map>
#include <vector>

#include <glm/glm.hpp>

#include "scene/mesh/model.h"
#include "scene/mesh/normals_by_angle.h"
#include "scene/reading/import_choices.h"
#include "scene/reading/import_limits.h"

namespace toond::scene {

// The warnings of one import. A broken export can repeat one complaint per
// face; the answer must stay readable, so each message is kept once and at
// most kMaxWarnings are kept at all.
// The warnings of one import, grouped and capped, so no answer carries more
// than a few kilobytes of them whatever the input: a message repeated is
// kept once with its count ("100000 × …"), at most kMaxWarnings distinct
// ones are kept, each at most kMaxMessageBytes long.
class ImportWarnings {
 public:
  static constexpr std::size_t kMaxWarnings = 40;
  static constexpr std::size_t kMaxMessageBytes = 240;

  void add(std::string message);
  // A count the whole import adds up once (degenerate or repeated triangles
  // dropped): kept even when kMaxWarnings others came first, since a file
  // that repeats a face 100,000 times under new material names fills the
  // list with those names before the repeats are counted. Sanitised and
  // cut like any other.
  void add_summary(std::string message);
  // The list, repeats counted, with a closing note when some were left out.
  std::vector<std::string> take();

 private:
  std::vector<std::string> list_;
  std::vector<std::string> summaries_;
  std::vector<std::size_t> counts_;  // per entry of list_
  // Every distinct message seen: its index in list_, or kDropped.
  std::unordered_map<std::string, std::size_t> seen_;
  static constexpr std::size_t kDropped = ~std::size_t{0};
  std::size_t dropped_ = 0;
};

struct SourceCorner {
  std::uint32_t position = 0;  // into MeshSource::positions
  std::int64_t normal = -1;    // into MeshSource::normals, -1 = none
  std::int64_t texcoord = -1;  // into MeshSource::texcoords, -1 = none
  std::int64_t tangent = -1;   // into MeshSource::tangents, -1 = none (computed)
};

struct SourceTriangle {
  SourceCorner corner[3];
  // The importer's own material id until build_mesh's assign_materials has
  // run, an index into Model::materials after.
  int material = -1;
  // OBJ smoothing group, 0 = none or off. Only consulted for corners
  // without a usable normal.
  unsigned smoothing = 0;
};

// A model as its file lists it, in double precision, not yet checked.
struct MeshSource {
  std::string file;  // the bundle path: named in messages and ImportError::file
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals;  // need not be unit length, may be unusable
  std::vector<glm::dvec2> texcoords;
  // The file's own tangents (glTF TANGENT): xyz along the texture's u, w the
  // bitangent's handedness (±1); need not be unit length, may be unusable.
  std::vector<glm::dvec4> tangents;
  std::vector<glm::dvec3> colors;  // empty, or one per position (0..1 expected)
  // Empty, or one per position: how it moves (Rig::motions); carried to
  // every vertex made from the position as Mesh::motion.
  std::vector<std::uint32_t> motions;
  std::vector<SourceTriangle> triangles;
  // Names position `i` in messages, e.g. "vertex 12 (line 40)"; only called
  // on failure. Unset: "vertex i+1".
  std::function<std::string(std::size_t)> describe_position;
  // Vertex and triangle counts allowed (ImportLimitError beyond).
  ImportLimits limits;
  // Corners without a usable normal, where no smoothing groups decide, are
  // smoothed across edges whose faces turn by less than this (degrees):
  // 0 gives flat faces (glTF's rule), 180 smooths every edge.
  double smooth_angle_deg = kDefaultSmoothAngle;
  // The file is Z-up: positions, normals and tangents are turned so that
  // its +Z becomes +Y, (x, y, z) → (x, z, −y), before anything else.
  bool z_up = false;
};

// Builds the mesh of `source` (whose triangles it consumes):
// - more positions or triangles than source.limits allow is an
//   ImportLimitError saying which;
// - every position must be finite, every corner's position index in range
//   (ImportError naming the file, and the vertex or triangle); normal and
//   texcoord indices out of range are dropped with a warning;
// - positions are recentred on the centre of the used positions' box,
//   computed in double (Mesh::origin); an extent beyond float range is an
//   ImportError;
// - triangles with no area, in the file's numbers or after rounding to
//   float, are dropped with a warning; none left is an ImportError;
// - triangles whose corners repeat another's (in any rotation) are
//   dropped, the one drawn last kept, with a warning that counts them;
// - assign_materials(triangles) then sets every remaining triangle's
//   material to an index into the model's materials (so an importer can
//   keep only the materials in use);
// - vertices are shared by (position, normal, texcoord, smoothing), so a
//   position's colour goes with every vertex made from it; normals that
//   are missing, zero or not finite are computed (angle-weighted, averaged
//   per position within the smoothing group or, with smoothing off where
//   groups are used, the face; without smoothing groups over the faces
//   joined across edges sharper than source.smooth_angle_deg, a vertex
//   copied for each such group: normals by angle); texcoords that are not finite
//   become (0,0) and colours are sanitised, each with a warning;
// - outline normals, tangents and bounds are derived (a corner's usable
//   file tangent is kept instead of the derived one), and triangles are
//   sorted (stably) into one submesh per material.
// The turn a Z-up file's coordinates get, (x, y, z) → (x, z, −y), so its
// +Z becomes +Y; the identity for a Y-up file. build_mesh applies it to
// positions, normals and tangents; an importer turns what it keeps beside
// the mesh (a rig's deltas and matrices) with the same matrix.
glm::dmat3 up_axis_turn(bool z_up);

// Sets what the upload's choices say of the mesh: the smoothing angle and
// the up axis.
void apply_import_choices(MeshSource& source, const ImportChoices& choices);

Mesh build_mesh(MeshSource& source, ImportWarnings& warnings,
                const std::function<void(std::vector<SourceTriangle>&)>& assign_materials);

// The model of a format without materials (.m, STL, PLY): its mesh, one
// material named "default" (0.8 grey, or white under vertex colours, which
// then show as painted, as a texture would), and the import's warnings.
Model build_single_material_model(MeshSource& source, ImportWarnings& warnings);

}  // namespace toond::scene
