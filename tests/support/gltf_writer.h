#pragma once
// Writes glTF 2.0 test models in every form an upload can take: a .glb, a
// .gltf with a separate .bin and image files, or a .gltf carrying all of it
// as data: URIs. Tests build a GltfDocument, or tamper with the JSON and
// binary that build_gltf makes before packing them.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace toond::test {

struct GltfPrimitive {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;      // empty, or one per position
  std::vector<glm::vec2> texcoords;    // glTF orientation: v runs down the image
  std::vector<glm::vec4> colours;      // linear RGBA, empty or one per position
  std::vector<glm::vec4> tangents;     // xyz, w handedness; empty or one per position
  std::vector<std::uint32_t> indices;  // empty: not indexed
  int mode = 4;                        // triangles
  int material = -1;
};

struct GltfNode {
  int mesh = -1;
  std::vector<int> children;
  std::optional<std::array<double, 16>> matrix;  // column-major
  std::optional<glm::dvec3> translation;
  std::optional<glm::dvec4> rotation;  // quaternion x, y, z, w
  std::optional<glm::dvec3> scale;
};

struct GltfImage {
  std::string bytes;
  std::string mime_type = "image/png";
  std::string file_name = "texture.png";  // for GltfForm::SeparateFiles
};

// One glTF material; `json` is merged in last (alphaMode, extensions, ...).
struct GltfMaterial {
  glm::vec4 base_colour{1.0f};
  int base_colour_image = -1;  // index into GltfDocument::images (a texture per image)
  int normal_image = -1;
  nlohmann::json json = nlohmann::json::object();
};

struct GltfDocument {
  std::vector<std::vector<GltfPrimitive>> meshes;
  std::vector<GltfNode> nodes;
  std::vector<int> scene_roots;  // empty: one node per mesh at the origin
  std::vector<GltfMaterial> materials;
  std::vector<GltfImage> images;
};

// The JSON (buffer 0 without a URI, images in buffer views) and the one
// binary buffer of a document.
struct GltfParts {
  nlohmann::json json;
  std::string bin;
};
GltfParts build_gltf(const GltfDocument& document);

using GltfFiles = std::vector<std::pair<std::string, std::string>>;
enum class GltfForm { Glb, SeparateFiles, DataUris };

// Bundle files for `parts` named after `stem` ("model" → model.glb, or
// model.gltf + model.bin [+ the images' files]).
GltfFiles pack_gltf(const GltfParts& parts, GltfForm form, const std::string& stem = "model",
                    const std::vector<GltfImage>& images = {});
GltfFiles write_gltf(const GltfDocument& document, GltfForm form, const std::string& stem = "model");

// `bytes` as a base64 data: URI of `media_type`.
std::string data_uri(const std::string& bytes, const std::string& media_type);

// Numbers per element of an accessor `type` ("SCALAR" 1 ... "MAT4" 16).
std::size_t components_of(const std::string& type);

// Adds `extension` to the document's `list` ("extensionsUsed",
// "extensionsRequired") unless it is there.
void list_extension(nlohmann::json& doc, const char* list, const char* extension);

}  // namespace toond::test
