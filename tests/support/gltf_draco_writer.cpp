#include "support/gltf_draco_writer.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "helpers/draco_decode/draco_wire.h"
#include "helpers/launch/child_process.h"

namespace toond::test {
namespace {

using nlohmann::json;

constexpr const char* kDracoExtension = "KHR_draco_mesh_compression";

std::string draco_type_of(const std::string& semantic) {
  if (semantic == "POSITION") return "position";
  if (semantic == "NORMAL") return "normal";
  if (semantic.starts_with("TEXCOORD_")) return "texcoord";
  if (semantic.starts_with("COLOR_")) return "color";
  return "generic";
}

// The bytes of an accessor of `plain` (tightly packed, as build_gltf writes them).
const char* accessor_bytes(const GltfParts& plain, const json& accessor) {
  const json& view = plain.json["bufferViews"][accessor["bufferView"].get<std::size_t>()];
  return plain.bin.data() + view["byteOffset"].get<std::size_t>() + accessor.value("byteOffset", std::size_t{0});
}

std::uint32_t u32_at(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < 4; ++i)
    v |= static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[at + i])) << (8 * i);
  return v;
}

struct Encoded {
  std::string bytes;
  std::uint32_t points = 0;
  std::uint32_t faces = 0;
  json ids = json::object();  // semantic → Draco attribute id
};

// Encodes one primitive with toond-test-draco-encode (Draco cannot share
// this process with the importer: see tests/support/draco_encode_main.cpp).
Encoded encode_primitive(const GltfParts& plain, const json& primitive, const DracoOptions& options) {
  const json& accessors = plain.json["accessors"];
  const json& index_accessor = accessors[primitive["indices"].get<std::size_t>()];
  draco_wire::Mesh mesh;
  mesh.points = accessors[primitive["attributes"]["POSITION"].get<std::size_t>()]["count"].get<std::uint32_t>();
  mesh.indices.resize(index_accessor["count"].get<std::size_t>());
  std::memcpy(mesh.indices.data(), accessor_bytes(plain, index_accessor), mesh.indices.size() * 4);
  scene::ChildRun run;
  run.program = TOOND_DRACO_ENCODER_PATH;
  run.arguments = {"--bits", std::to_string(options.quantization_bits)};
  std::vector<std::string> semantics;
  for (const auto& [semantic, index] : primitive["attributes"].items()) {
    const json& accessor = accessors[index.get<std::size_t>()];
    draco_wire::Attribute attribute;
    attribute.components = components_of(accessor["type"]);
    const char* values = accessor_bytes(plain, accessor);
    attribute.values.assign(values, values + std::size_t{mesh.points} * attribute.components * 4);
    mesh.attributes.push_back(std::move(attribute));
    run.arguments.insert(run.arguments.end(), {"--type", draco_type_of(semantic)});
    semantics.push_back(semantic);
  }
  const std::string input = draco_wire::write_mesh(mesh);
  run.input = input;
  run.max_output = std::size_t{256} << 20;
  const scene::ChildResult result = scene::run_child(run);
  if (result.end != scene::ChildResult::End::Exited || result.code != 0 || result.output.size() < 16 ||
      result.output.substr(0, 4) != "TDE1") {
    throw std::runtime_error("toond-test-draco-encode failed: " + result.errors);
  }
  Encoded out;
  out.points = u32_at(result.output, 4);
  out.faces = u32_at(result.output, 8);
  const std::size_t count = u32_at(result.output, 12);
  for (std::size_t k = 0; k < count; ++k) out.ids[semantics[k]] = u32_at(result.output, 16 + 4 * k);
  out.bytes = result.output.substr(16 + 4 * count);
  return out;
}

}  // namespace

GltfParts draco_compress(const GltfParts& plain, const DracoOptions& options) {
  GltfParts out = plain;
  for (json& mesh : out.json["meshes"]) {
    for (json& primitive : mesh["primitives"]) {
      if (primitive.value("mode", 4) != 4 || !primitive.contains("indices")) continue;
      const Encoded encoded = encode_primitive(plain, primitive, options);
      while (out.bin.size() % 4 != 0) out.bin.push_back('\0');
      out.json["bufferViews"].push_back(
          {{"buffer", 0}, {"byteOffset", out.bin.size()}, {"byteLength", encoded.bytes.size()}});
      out.bin += encoded.bytes;
      primitive["extensions"][kDracoExtension] = {{"bufferView", out.json["bufferViews"].size() - 1},
                                                  {"attributes", encoded.ids}};
      const auto describe_decoded = [&](const json& index, std::size_t count) {
        json& accessor = out.json["accessors"][index.get<std::size_t>()];
        accessor["count"] = count;
        if (options.keep_fallback) {
          const json& view = out.json["bufferViews"][accessor["bufferView"].get<std::size_t>()];
          std::fill_n(out.bin.begin() + view["byteOffset"].get<std::ptrdiff_t>(), view["byteLength"].get<std::size_t>(),
                      options.fallback_fill);
        } else {
          accessor.erase("bufferView");
          accessor.erase("byteOffset");
        }
      };
      for (const auto& [semantic, index] : primitive["attributes"].items()) describe_decoded(index, encoded.points);
      describe_decoded(primitive["indices"], std::size_t{encoded.faces} * 3);
    }
  }
  while (out.bin.size() % 4 != 0) out.bin.push_back('\0');
  out.json["buffers"][0]["byteLength"] = out.bin.size();
  list_extension(out.json, "extensionsUsed", kDracoExtension);
  if (!options.keep_fallback) list_extension(out.json, "extensionsRequired", kDracoExtension);
  return out;
}

}  // namespace toond::test
