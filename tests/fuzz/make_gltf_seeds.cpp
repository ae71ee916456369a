// Writes the glTF fuzz target's seed corpus into the folder given: small
// valid files of every feature the importer reads (made by the tests' glTF
// writer, so they follow the importer's tests) plus a few broken ones.
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "support/gltf_meshopt_writer.h"
#include "support/gltf_rig_writer.h"
#include "support/gltf_writer.h"

namespace {

using namespace toond::test;

GltfPrimitive quad(int material) {
  GltfPrimitive p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  p.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  p.texcoords = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  p.colours = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}, {1, 1, 1, 0.5f}};
  p.indices = {0, 1, 2, 0, 2, 3};
  p.material = material;
  return p;
}

// A 1x1 PNG, enough for the image path.
const std::string kPng(
    "\x89\x50\x4e\x47\x0d\x0a\x1a\x0a\x00\x00\x00\x0d\x49\x48\x44\x52"
    "\x00\x00\x00\x01\x00\x00\x00\x01\x08\x02\x00\x00\x00\x90\x77\x53"
    "\xde\x00\x00\x00\x0c\x49\x44\x41\x54\x78\x9c\x63\xf8\xdf\xc0\x00"
    "\x00\x04\x01\x01\x80\xc5\x2a\x18\x5d\x00\x00\x00\x00\x49\x45\x4e"
    "\x44\xae\x42\x60\x82",
    69);

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_gltf_seeds FOLDER\n");
    return 2;
  }
  const std::filesystem::path dir = argv[1];
  std::filesystem::create_directories(dir);
  const auto save = [&](const std::string& name, const std::string& bytes) {
    std::ofstream(dir / name, std::ios::binary) << bytes;
  };

  GltfDocument doc;
  GltfPrimitive strip = quad(1);
  strip.indices.clear();
  strip.mode = 5;
  doc.meshes = {{quad(0), strip}};
  GltfNode root;
  root.children = {1};
  root.translation = glm::dvec3(3, 0, 0);
  GltfNode child;
  child.mesh = 0;
  child.rotation = glm::dvec4(0, 0, 0.7071, 0.7071);
  child.scale = glm::dvec3(2, 2, 2);
  doc.nodes = {root, child};
  doc.scene_roots = {0};
  doc.images = {{kPng, "image/png", "t.png"}};
  GltfMaterial textured;
  textured.base_colour_image = 0;
  textured.normal_image = 0;
  textured.json = {{"alphaMode", "MASK"}, {"emissiveFactor", {0.1, 0, 0}}};
  GltfMaterial plain;
  plain.base_colour = {0.2f, 0.4f, 0.6f, 1};
  plain.json = {{"extensions", {{"KHR_materials_unlit", nlohmann::json::object()}}}};
  doc.materials = {textured, plain};

  save("features.glb", write_gltf(doc, GltfForm::Glb)[0].second);
  save("features.gltf", write_gltf(doc, GltfForm::DataUris)[0].second);

  GltfParts parts = build_gltf(doc);
  parts.json["accessors"][0]["sparse"] = {
      {"count", 1}, {"indices", {{"bufferView", 3}, {"componentType", 5125}}}, {"values", {{"bufferView", 0}}}};
  parts.json["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"] = {
      {"KHR_texture_transform", {{"offset", {0.5, 0}}, {"rotation", 0.3}, {"scale", {2, 2}}}}};
  parts.json["extensionsRequired"] = {"KHR_texture_transform"};
  save("sparse-transform.glb", pack_gltf(parts, GltfForm::Glb)[0].second);

  // EXT_meshopt_compression as gltfpack writes it: every mesh view a
  // stream in the binary chunk, the views themselves in a stand-in buffer
  // without data.
  save("meshopt.glb", pack_gltf(meshopt_compress(build_gltf(doc)), GltfForm::Glb)[0].second);

  // KHR_draco_mesh_compression on the first primitive: its accessors lose
  // their views and its data is a Draco header over noise. The fuzz targets
  // run without the decoder helper, so this seed reaches what comes before
  // the decode (the extension object, the indices kept from tinygltf, the
  // counts) and its refusal.
  parts = build_gltf(doc);
  std::string draco("DRACO\x02\x02\x01\x01\x00\x00", 11);
  for (int i = 0; i < 53; ++i) draco.push_back(static_cast<char>(i * 37 + 11));
  while (parts.bin.size() % 4 != 0) parts.bin.push_back('\0');
  parts.json["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", parts.bin.size()}, {"byteLength", draco.size()}});
  parts.bin += draco;
  parts.json["buffers"][0]["byteLength"] = parts.bin.size();
  nlohmann::json& primitive = parts.json["meshes"][0]["primitives"][0];
  primitive["extensions"]["KHR_draco_mesh_compression"] = {
      {"bufferView", parts.json["bufferViews"].size() - 1},
      {"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}, {"COLOR_0", 3}}}};
  for (const auto& [semantic, accessor] : primitive["attributes"].items()) {
    parts.json["accessors"][accessor.get<std::size_t>()].erase("bufferView");
  }
  parts.json["accessors"][primitive["indices"].get<std::size_t>()].erase("bufferView");
  parts.json["extensionsUsed"] = {"KHR_draco_mesh_compression"};
  parts.json["extensionsRequired"] = {"KHR_draco_mesh_compression"};
  save("draco.glb", pack_gltf(parts, GltfForm::Glb)[0].second);

  parts = build_gltf(doc);
  parts.json["accessors"][0]["count"] = 2000000000;
  save("huge-count.glb", pack_gltf(parts, GltfForm::Glb)[0].second);
  const std::string glb = write_gltf(doc, GltfForm::Glb)[0].second;
  save("truncated.glb", glb.substr(0, glb.size() / 2));
  std::printf("wrote the glTF seed corpus to %s\n", dir.c_str());
  // What moves: a bar of three rings skinned to a chain of two joints (two
  // weight sets), a morph target, and a clip with LINEAR, STEP and
  // CUBICSPLINE channels on rotation, translation and weights.
  GltfDocument rigged;
  rigged.meshes = {{bar_primitive(3)}};
  rigged.nodes.resize(3);
  rigged.nodes[0].mesh = 0;
  rigged.nodes[1].children = {2};
  rigged.nodes[2].translation = glm::dvec3(0, 1, 0);
  rigged.scene_roots = {0, 1};
  GltfParts rig = build_gltf(rigged);
  std::vector<std::uint16_t> joints;
  std::vector<float> weights;
  for (int v = 0; v < 12; ++v) {
    joints.insert(joints.end(), {0, 1, 0, 0});
    weights.insert(weights.end(), {1.0f - v / 12.0f, v / 12.0f, 0, 0});
  }
  nlohmann::json& attributes = rig.json["meshes"][0]["primitives"][0]["attributes"];
  attributes["JOINTS_0"] = append_joints_accessor(rig, joints);
  attributes["WEIGHTS_0"] = append_float_accessor(rig, weights, "VEC4");
  attributes["JOINTS_1"] = append_joints_accessor(rig, joints);
  attributes["WEIGHTS_1"] = append_float_accessor(rig, std::vector<float>(48, 0.0f), "VEC4");
  rig.json["meshes"][0]["primitives"][0]["targets"] = {
      {{"POSITION", append_float_accessor(rig, std::vector<float>(36, 0.25f), "VEC3")}}};
  rig.json["meshes"][0]["weights"] = {0.5};
  rig.json["skins"] = {
      {{"joints", {1, 2}},
       {"inverseBindMatrices", append_float_accessor(rig, {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0,  0, 1,
                                                           1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -1, 0, 1},
                                                     "MAT4")}}};
  rig.json["nodes"][0]["skin"] = 0;
  const int times = append_float_accessor(rig, {0.0f, 0.5f, 1.25f}, "SCALAR");
  const int turns = append_float_accessor(rig, {0, 0, 0, 1, 0, 0, 0.7071f, 0.7071f, 0, 0, 1, 0}, "VEC4");
  const int moves = append_float_accessor(rig, {0, 0, 0, 1, 0, 0, 0, 2, 0}, "VEC3");
  // CUBICSPLINE: in-tangent, value, out-tangent per key.
  const int morphs = append_float_accessor(rig, {0, 0, 1, 1, 1, 0, 0, 0.5f, 0}, "SCALAR");
  rig.json["animations"] = {{{"name", "Armature|Bend"},
                             {"samplers",
                              {{{"input", times}, {"output", turns}},
                               {{"input", times}, {"output", moves}, {"interpolation", "STEP"}},
                               {{"input", times}, {"output", morphs}, {"interpolation", "CUBICSPLINE"}}}},
                             {"channels",
                              {{{"sampler", 0}, {"target", {{"node", 2}, {"path", "rotation"}}}},
                               {{"sampler", 1}, {"target", {{"node", 1}, {"path", "translation"}}}},
                               {{"sampler", 2}, {"target", {{"node", 0}, {"path", "weights"}}}}}}}};
  save("rigged.glb", pack_gltf(rig, GltfForm::Glb)[0].second);
  return 0;
}
