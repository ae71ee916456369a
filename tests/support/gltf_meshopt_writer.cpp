#include "support/gltf_meshopt_writer.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <vector>

namespace toond::test {
namespace {

using nlohmann::json;

constexpr const char* kMeshoptExtension = "EXT_meshopt_compression";

void pad_to_four(std::string& bytes) {
  while (bytes.size() % 4 != 0) bytes.push_back('\0');
}

std::vector<unsigned int> indices_of(const void* elements, std::size_t count, std::size_t stride) {
  std::vector<unsigned int> indices(count);
  const auto* bytes = static_cast<const unsigned char*>(elements);
  for (std::size_t i = 0; i < count; ++i) {
    if (stride == 2) {
      std::uint16_t v;
      std::memcpy(&v, bytes + 2 * i, 2);
      indices[i] = v;
    } else {
      std::memcpy(&indices[i], bytes + 4 * i, 4);
    }
  }
  return indices;
}

std::string encode_stream(const void* elements, std::size_t count, std::size_t stride, const std::string& mode) {
  std::vector<unsigned char> out;
  if (mode == "ATTRIBUTES") {
    out.resize(meshopt_encodeVertexBufferBound(count, stride));
    out.resize(meshopt_encodeVertexBuffer(out.data(), out.size(), elements, count, stride));
  } else {
    const std::vector<unsigned int> indices = indices_of(elements, count, stride);
    const std::size_t vertices = indices.empty() ? 0 : *std::max_element(indices.begin(), indices.end()) + 1;
    // The extension's bitstreams are the codecs' version 1.
    meshopt_encodeIndexVersion(1);
    if (mode == "TRIANGLES") {
      out.resize(meshopt_encodeIndexBufferBound(count, vertices));
      out.resize(meshopt_encodeIndexBuffer(out.data(), out.size(), indices.data(), count));
    } else {
      out.resize(meshopt_encodeIndexSequenceBound(count, vertices));
      out.resize(meshopt_encodeIndexSequence(out.data(), out.size(), indices.data(), count));
    }
  }
  return std::string(out.begin(), out.end());
}

// Appends the stream to buffer 0 and room for the view to the stand-in
// buffer 1; returns the view's JSON.
json compressed_view(GltfParts& parts, const void* elements, std::size_t count, std::size_t stride,
                     const std::string& mode, const std::string& filter) {
  json& buffers = parts.json["buffers"];
  if (buffers.size() < 2) {
    buffers.push_back({{"byteLength", 0}, {"extensions", {{kMeshoptExtension, {{"fallback", true}}}}}});
  }
  const std::string stream = encode_stream(elements, count, stride, mode);
  pad_to_four(parts.bin);
  const std::size_t stream_offset = parts.bin.size();
  parts.bin += stream;
  buffers[0]["byteLength"] = parts.bin.size();
  std::size_t view_offset = buffers[1]["byteLength"].get<std::size_t>();
  view_offset += (4 - view_offset % 4) % 4;
  buffers[1]["byteLength"] = view_offset + count * stride;
  list_extension(parts.json, "extensionsUsed", kMeshoptExtension);
  list_extension(parts.json, "extensionsRequired", kMeshoptExtension);
  json view = {{"buffer", 1}, {"byteOffset", view_offset}, {"byteLength", count * stride}};
  json extension = {{"buffer", 0},
                    {"byteOffset", stream_offset},
                    {"byteLength", stream.size()},
                    {"byteStride", stride},
                    {"count", count},
                    {"mode", mode}};
  if (filter != "NONE") extension["filter"] = filter;
  view["extensions"] = {{kMeshoptExtension, extension}};
  return view;
}

std::size_t component_size(int component_type) {
  return component_type == 5120 || component_type == 5121   ? 1
         : component_type == 5122 || component_type == 5123 ? 2
                                                            : 4;
}

std::size_t component_count(const std::string& type) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  return 4;
}

}  // namespace

int add_meshopt_view(GltfParts& parts, const void* elements, std::size_t count, std::size_t stride,
                     const std::string& mode, const std::string& filter) {
  json view = compressed_view(parts, elements, count, stride, mode, filter);
  parts.json["bufferViews"].push_back(std::move(view));
  return static_cast<int>(parts.json["bufferViews"].size()) - 1;
}

GltfParts meshopt_compress(const GltfParts& plain, MeshoptFallback fallback) {
  // How each view is read: the mode its accessors need and their element size.
  std::map<std::size_t, std::pair<std::string, std::size_t>> streams;
  const auto note = [&](const json& accessor_index, const std::string& mode) {
    const json& accessor = plain.json["accessors"][accessor_index.get<std::size_t>()];
    const std::size_t element =
        component_size(accessor["componentType"].get<int>()) * component_count(accessor["type"].get<std::string>());
    streams[accessor["bufferView"].get<std::size_t>()] = {mode, element};
  };
  for (const json& mesh : plain.json["meshes"]) {
    for (const json& primitive : mesh["primitives"]) {
      for (const auto& [semantic, accessor] : primitive["attributes"].items()) note(accessor, "ATTRIBUTES");
      if (primitive.contains("indices")) {
        note(primitive["indices"], primitive.value("mode", 4) == 4 ? "TRIANGLES" : "INDICES");
      }
    }
  }

  GltfParts out{plain.json, {}};
  out.json["buffers"] = json::array({{{"byteLength", 0}}});
  json& views = out.json["bufferViews"];
  for (std::size_t i = 0; i < views.size(); ++i) {
    const json& original = plain.json["bufferViews"][i];
    const std::string bytes =
        plain.bin.substr(original["byteOffset"].get<std::size_t>(), original["byteLength"].get<std::size_t>());
    if (const auto it = streams.find(i); it != streams.end()) {
      const auto [mode, stride] = it->second;
      views[i] = compressed_view(out, bytes.data(), bytes.size() / stride, stride, mode, "NONE");
    } else {
      pad_to_four(out.bin);
      views[i]["byteOffset"] = out.bin.size();
      out.bin += bytes;
    }
  }
  pad_to_four(out.bin);
  out.json["buffers"][0]["byteLength"] = out.bin.size();

  json& stand_in = out.json["buffers"][1];
  if (fallback != MeshoptFallback::StandIn) stand_in.erase("extensions");
  if (fallback == MeshoptFallback::Zeros) {
    stand_in["uri"] =
        data_uri(std::string(stand_in["byteLength"].get<std::size_t>(), '\0'), "application/octet-stream");
    json& required = out.json["extensionsRequired"];
    required.erase(std::remove(required.begin(), required.end(), kMeshoptExtension), required.end());
    if (required.empty()) out.json.erase("extensionsRequired");
  }
  return out;
}

}  // namespace toond::test
