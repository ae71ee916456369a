#pragma once
// KHR_draco_mesh_compression: primitives whose vertices and indices are a
// Draco mesh in a buffer view. The mesh is decoded in the helper process
// (draco_decoder.h); its attributes and indices become accessors of their
// own over buffer views the importer holds, so the accessor reader and
// everything after it see an ordinary triangle list.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/gltf/gltf_accessor.h"
#include "scene/reading/import_limits.h"

namespace tinygltf {
class Model;
}  // namespace tinygltf

namespace toond::scene {

struct DracoPrimitive {
  int mesh = 0;
  std::size_t primitive = 0;
  int buffer_view = -1;                             // the Draco bytes
  std::map<std::string, std::uint32_t> attributes;  // semantic → Draco attribute id
  int indices = -1;                                 // the primitive's index accessor, if any
};

// The Draco primitives of `doc`, with their `indices` taken out of the
// JSON: tinygltf (Debian's is built without Draco) refuses an index
// accessor without a buffer view, which is how a Draco primitive's indices
// are written. Give them back with restore_draco_indices once tinygltf has
// read the document. An extension object without a buffer view, or with an
// attribute id that is not a non-negative integer, is an ImportError naming
// the primitive.
std::vector<DracoPrimitive> take_draco_primitives(nlohmann::json& doc, const std::string& file);

void restore_draco_indices(const std::vector<DracoPrimitive>& primitives, tinygltf::Model& gltf);

// Decodes `primitive` and rewrites it in `gltf` as a triangle list whose
// decoded attributes and indices are new accessors over new buffer views
// (a Draco primitive's own accessors only describe the data). The new
// views' bytes go to `views` under their index. Before that, the decoded
// mesh must match the primitive's accessors: as many points as each
// accessor of a decoded attribute counts, as many triangles as its indices
// make, the components each accessor's type has. A decoder that fails,
// crashes or runs out of time, and a mesh that does not match, is an
// ImportError naming the primitive; running past `limits.deadline` is an
// ImportLimitError.
void decode_draco_primitive(const DracoPrimitive& primitive, tinygltf::Model& gltf, const GltfAccessorReader& reader,
                            std::map<int, std::vector<std::uint8_t>>& views, const ImportLimits& limits,
                            const std::string& file);

}  // namespace toond::scene
