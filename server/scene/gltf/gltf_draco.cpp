#include "scene/gltf/gltf_draco.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>

#include "scene/gltf/draco_decoder.h"
#include "scene/gltf/gltf_json.h"
#include "scene/reading/import_error.h"

namespace toond::scene {
namespace {

using namespace gltf_json;

constexpr const char* kExtension = "KHR_draco_mesh_compression";

std::string primitive_name(int mesh, std::size_t primitive) {
  return "mesh " + std::to_string(mesh) + " primitive " + std::to_string(primitive);
}

bool is_triangles(int mode) {
  return mode == TINYGLTF_MODE_TRIANGLES || mode == TINYGLTF_MODE_TRIANGLE_STRIP || mode == TINYGLTF_MODE_TRIANGLE_FAN;
}

std::uint64_t triangles_of(int mode, std::uint64_t corners) {
  if (mode == TINYGLTF_MODE_TRIANGLES) return corners / 3;
  return corners < 3 ? 0 : corners - 2;
}

int add_view(tinygltf::Model& gltf, std::map<int, std::vector<std::uint8_t>>& views, std::vector<std::uint8_t> bytes) {
  tinygltf::BufferView view;
  view.buffer = -1;  // the bytes are the importer's, not a buffer's
  view.byteLength = bytes.size();
  gltf.bufferViews.push_back(view);
  const int index = static_cast<int>(gltf.bufferViews.size()) - 1;
  views[index] = std::move(bytes);
  return index;
}

int add_accessor(tinygltf::Model& gltf, const tinygltf::Accessor& accessor) {
  gltf.accessors.push_back(accessor);
  return static_cast<int>(gltf.accessors.size()) - 1;
}

// The time one decode may take: the helper's own limit, or what is left
// of the import's, rounded up: a helper stopped for the import's time must
// be stopped at or after the import's deadline, so that the deadline's
// check afterwards reports the import's limit and not a slow decoder.
std::chrono::milliseconds time_for_decode(const ImportLimits& limits) {
  const auto now = std::chrono::steady_clock::now();
  if (limits.deadline == std::chrono::steady_clock::time_point::max()) return kDracoTimeLimit;
  return std::clamp(std::chrono::ceil<std::chrono::milliseconds>(limits.deadline - now), std::chrono::milliseconds(1),
                    kDracoTimeLimit);
}

}  // namespace

std::vector<DracoPrimitive> take_draco_primitives(nlohmann::json& doc, const std::string& file) {
  std::vector<DracoPrimitive> found;
  const auto meshes = doc.find("meshes");
  if (meshes == doc.end() || !meshes->is_array()) return found;
  for (std::size_t m = 0; m < meshes->size(); ++m) {
    json& mesh = (*meshes)[m];
    const auto primitives = mesh.is_object() ? mesh.find("primitives") : mesh.end();
    if (!mesh.is_object() || primitives == mesh.end() || !primitives->is_array()) continue;
    for (std::size_t p = 0; p < primitives->size(); ++p) {
      json& primitive = (*primitives)[p];
      const json& extension = member(member(primitive, "extensions"), kExtension);
      if (extension.is_null()) continue;
      const auto fail = [&](const std::string& why) {
        throw ImportError(file, file + ": " + primitive_name(static_cast<int>(m), p) + " (" + kExtension + ") " + why);
      };
      DracoPrimitive draco;
      draco.mesh = static_cast<int>(m);
      draco.primitive = p;
      draco.buffer_view = index_or(member(extension, "bufferView"), -1);
      if (draco.buffer_view < 0) fail("has no valid bufferView");
      const json& attributes = member(extension, "attributes");
      if (!attributes.is_object()) fail("has no attributes object");
      for (const auto& [semantic, value] : attributes.items()) {
        const auto id = unsigned_of(value);
        if (!id || *id > UINT32_MAX) fail("gives " + semantic + " an attribute id that is not a non-negative integer");
        draco.attributes[semantic] = static_cast<std::uint32_t>(*id);
      }
      draco.indices = index_or(member(primitive, "indices"), -1);
      primitive.erase("indices");
      found.push_back(std::move(draco));
    }
  }
  return found;
}

void restore_draco_indices(const std::vector<DracoPrimitive>& primitives, tinygltf::Model& gltf) {
  for (const DracoPrimitive& draco : primitives) {
    if (static_cast<std::size_t>(draco.mesh) >= gltf.meshes.size()) continue;
    auto& mesh_primitives = gltf.meshes[static_cast<std::size_t>(draco.mesh)].primitives;
    if (draco.primitive < mesh_primitives.size()) mesh_primitives[draco.primitive].indices = draco.indices;
  }
}

void decode_draco_primitive(const DracoPrimitive& draco, tinygltf::Model& gltf, const GltfAccessorReader& reader,
                            std::map<int, std::vector<std::uint8_t>>& views, const ImportLimits& limits,
                            const std::string& file) {
  tinygltf::Primitive& primitive = gltf.meshes.at(static_cast<std::size_t>(draco.mesh)).primitives.at(draco.primitive);
  if (!is_triangles(primitive.mode)) return;  // not drawn, so not decoded
  const std::string name = primitive_name(draco.mesh, draco.primitive);
  const auto fail = [&](const std::string& why) {
    throw ImportError(file, file + ": " + name + " (" + kExtension + ") " + why);
  };
  const auto position = primitive.attributes.find("POSITION");
  if (position == primitive.attributes.end()) fail("has no POSITION attribute");
  const std::uint64_t points = reader.accessor(position->second, name + " POSITION").count;
  const std::uint64_t corners = draco.indices >= 0 ? reader.accessor(draco.indices, name + " indices").count : points;
  const std::uint64_t triangles = triangles_of(primitive.mode, corners);

  // Only attributes the primitive has an accessor for have somewhere to go.
  std::vector<std::pair<std::string, std::uint32_t>> decoded;
  for (const auto& [semantic, id] : draco.attributes) {
    if (primitive.attributes.contains(semantic)) decoded.emplace_back(semantic, id);
  }
  DracoJob job;
  job.data = reader.view(draco.buffer_view, name + " Draco data");
  for (const auto& entry : decoded) job.attributes.push_back(entry.second);
  job.max_points = points;
  job.max_indices = triangles * 3;
  job.time_limit = time_for_decode(limits);
  draco_wire::Mesh mesh;
  try {
    mesh = decode_draco_mesh(job);
  } catch (const DracoDecodeError& e) {
    // A decode stopped by the import's own deadline is that limit's answer.
    check_import_time(limits, "decoding the Draco data of " + name);
    fail(std::string("cannot be decoded: ") + e.what());
  }

  if (mesh.points != points) {
    fail("decodes to " + std::to_string(mesh.points) + " points, but its POSITION accessor counts " +
         std::to_string(points));
  }
  if (mesh.indices.size() != triangles * 3) {
    fail("decodes to " + std::to_string(mesh.indices.size() / 3) + " triangles, but its indices make " +
         std::to_string(triangles));
  }
  for (std::size_t k = 0; k < decoded.size(); ++k) {
    const std::string& semantic = decoded[k].first;
    draco_wire::Attribute& values = mesh.attributes[k];
    tinygltf::Accessor accessor = reader.accessor(primitive.attributes.at(semantic), name + " " + semantic);
    const int components = gltf_component_count(accessor.type);
    if (accessor.count != points) {
      fail("decodes " + std::to_string(points) + " points, but its " + semantic + " accessor counts " +
           std::to_string(accessor.count));
    }
    if (static_cast<int>(values.components) != components) {
      fail("decodes " + semantic + " with " + std::to_string(values.components) + " components, but its accessor has " +
           std::to_string(components));
    }
    // Floats are values as they are; integers keep the accessor's word on
    // whether they are normalised.
    accessor.normalized = accessor.normalized && values.component_type != draco_wire::kFloat;
    accessor.componentType = values.component_type;
    accessor.bufferView = add_view(gltf, views, std::move(values.values));
    accessor.byteOffset = 0;
    accessor.sparse.isSparse = false;
    primitive.attributes[semantic] = add_accessor(gltf, accessor);
  }

  std::vector<std::uint8_t> index_bytes(mesh.indices.size() * sizeof(std::uint32_t));
  if (!index_bytes.empty()) std::memcpy(index_bytes.data(), mesh.indices.data(), index_bytes.size());
  tinygltf::Accessor indices;
  indices.type = TINYGLTF_TYPE_SCALAR;
  indices.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
  indices.count = mesh.indices.size();
  indices.bufferView = add_view(gltf, views, std::move(index_bytes));
  primitive.indices = add_accessor(gltf, indices);
  // Draco decodes every mode to a list of triangles.
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
}

}  // namespace toond::scene
