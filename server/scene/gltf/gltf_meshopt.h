#pragma once
// EXT_meshopt_compression: a buffer view whose bytes are stored as a
// meshoptimizer stream in another buffer (gltfpack writes these, usually on
// top of KHR_mesh_quantization). The view is decoded the first time an
// accessor reads it, into exactly the bytes the uncompressed view would
// hold, so the accessor reader sees no difference.
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/reading/import_limits.h"

namespace tinygltf {
class Model;
}  // namespace tinygltf

namespace toond::scene {

enum class MeshoptMode { Attributes, Triangles, Indices };
enum class MeshoptFilter { None, Octahedral, Quaternion, Exponential };

// One compressed view, as its extension object describes it.
struct MeshoptStream {
  int buffer = -1;  // the buffer holding the compressed bytes
  std::uint64_t byte_offset = 0;
  std::uint64_t byte_length = 0;  // compressed bytes
  std::uint64_t byte_stride = 0;
  std::uint64_t count = 0;
  MeshoptMode mode = MeshoptMode::Attributes;
  MeshoptFilter filter = MeshoptFilter::None;
};

// The stream of buffer view `view` (its JSON object `view_json`), or
// nullopt when the view has no EXT_meshopt_compression object. An object
// that breaks the extension's rules (a missing or unknown field, a stride
// the mode or filter cannot have, a view whose byteLength is not count ×
// byteStride) is an ImportError naming the view.
std::optional<MeshoptStream> parse_meshopt_stream(const nlohmann::json& view_json, int view, const std::string& file);

// The count × byteStride bytes `stream` decodes to. `buffer` is the whole
// source buffer. Before anything is allocated, the compressed range must
// lie inside `buffer`, the count must be within `limits` (vertices for
// attributes, triangle corners for indices), and count × byteStride must be
// no more than the format can unpack from the compressed bytes. A stream
// that does not decode is an ImportError naming the view.
std::vector<std::uint8_t> decode_meshopt_stream(const MeshoptStream& stream, std::span<const std::uint8_t> buffer,
                                                int view, const ImportLimits& limits, const std::string& file);

// Whether buffer `buffer_json` is only a stand-in for the uncompressed
// views of a file that uses the extension: tagged as a fallback, or with no
// data at all (`has_data`: it has a URI or is the GLB's binary chunk).
bool is_meshopt_fallback(const nlohmann::json& buffer_json, bool has_data, bool file_uses_meshopt);

// The decoded views of one file, decoded on first use and kept.
class MeshoptViews {
 public:
  // `doc` is the file's JSON and `gltf` the model tinygltf made of it;
  // `fallbacks` are the buffers that were not loaded (is_meshopt_fallback).
  MeshoptViews(const nlohmann::json& doc, const tinygltf::Model& gltf, std::set<int> fallbacks, std::string file,
               ImportLimits limits);

  // The decoded bytes of `view`, or nullopt when the view is not
  // compressed and its buffer slice holds its bytes. A view that is not
  // compressed but lies in a fallback buffer is an ImportError.
  std::optional<std::span<const std::uint8_t>> bytes(int view);

 private:
  const nlohmann::json& doc_;
  const tinygltf::Model& gltf_;
  std::set<int> fallbacks_;
  std::string file_;
  ImportLimits limits_;
  std::map<int, std::vector<std::uint8_t>> decoded_;
};

}  // namespace toond::scene
