#include "scene/import/clip_merge.h"

#include <map>
#include <set>

#define GLM_ENABLE_EXPERIMENTAL
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtx/matrix_decompose.hpp>
#include <nlohmann/json.hpp>

#include "glb/glb_container.h"
#include "scene/gltf/data_uri.h"
#include "scene/gltf/gltf_container.h"
#include "scene/gltf/gltf_json.h"
#include "scene/reading/import_error.h"

namespace toond::scene {
namespace {

using nlohmann::json;
using namespace gltf_json;

struct Document {
  json doc;
  std::string bin;
};

Document parse(std::string_view bytes, const std::string& path) {
  const GltfContainer container = open_gltf_container(bytes, path);
  Document d;
  d.doc = json::parse(container.json, nullptr, false);
  if (!d.doc.is_object()) throw ImportError(path, path + ": its glTF JSON is not readable");
  if (container.bin) d.bin = std::string(*container.bin);
  return d;
}

// Copies accessors of the clip file, with the bytes of their views, into the
// model's document and its binary chunk.
class AccessorCopier {
 public:
  AccessorCopier(Document& model, int buffer, const Document& clips, const std::string& clips_path,
                 const BufferFiles& buffers)
      : model_(model), buffer_(buffer), clips_(clips), clips_path_(clips_path), buffers_(buffers) {}

  // The model's index of clip accessor `index`; throws ImportError when it
  // cannot be copied.
  int copy(int index) {
    if (const auto it = copied_.find(index); it != copied_.end()) return it->second;
    const json& accessor = element(member(clips_.doc, "accessors"), static_cast<std::size_t>(std::max(index, 0)));
    if (index < 0 || !accessor.is_object() || member(accessor, "sparse").is_object()) fail("a clip's keys");
    json out = accessor;
    const int view = index_or(member(accessor, "bufferView"), -1);
    if (view >= 0) out["bufferView"] = copy_view(view);
    model_.doc["accessors"].push_back(std::move(out));
    const int copied = static_cast<int>(model_.doc["accessors"].size()) - 1;
    copied_.emplace(index, copied);
    return copied;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw ImportError(clips_path_, clips_path_ + ": " + what + " cannot be read");
  }

  const std::string& buffer_bytes(int index) {
    if (const auto it = loaded_.find(index); it != loaded_.end()) return it->second;
    const json& buffer = element(member(clips_.doc, "buffers"), static_cast<std::size_t>(std::max(index, 0)));
    const json& uri = member(buffer, "uri");
    std::optional<std::string> bytes;
    if (!uri.is_string() && index == 0) {
      bytes = clips_.bin;
    } else if (uri.is_string() && is_data_uri(uri.get<std::string>())) {
      if (const auto decoded = decode_data_uri(uri.get<std::string>())) {
        bytes = std::string(decoded->bytes.begin(), decoded->bytes.end());
      }
    } else if (uri.is_string()) {
      bytes = buffers_(uri.get<std::string>());
    }
    if (!bytes) fail("buffer " + std::to_string(index));
    return loaded_.emplace(index, std::move(*bytes)).first->second;
  }

  int copy_view(int index) {
    const json& view = element(member(clips_.doc, "bufferViews"), static_cast<std::size_t>(index));
    const std::string& bytes = buffer_bytes(index_or(member(view, "buffer"), -1));
    const auto offset = unsigned_of(member(view, "byteOffset")).value_or(0);
    const auto length = unsigned_of(member(view, "byteLength")).value_or(0);
    if (offset > bytes.size() || length > bytes.size() - offset) fail("buffer view " + std::to_string(index));
    while (model_.bin.size() % 4 != 0) model_.bin.push_back('\0');
    json out = {{"buffer", buffer_}, {"byteOffset", model_.bin.size()}, {"byteLength", length}};
    if (const json& stride = member(view, "byteStride"); stride.is_number_unsigned()) out["byteStride"] = stride;
    model_.bin.append(bytes, offset, length);
    model_.doc["bufferViews"].push_back(std::move(out));
    return static_cast<int>(model_.doc["bufferViews"].size()) - 1;
  }

  Document& model_;
  int buffer_;
  const Document& clips_;
  const std::string& clips_path_;
  const BufferFiles& buffers_;
  std::map<int, int> copied_;
  std::map<int, std::string> loaded_;
};

// The model's binary chunk as buffer 0, made so where the model had none
// (every buffer index moves up one).
void make_binary_buffer(Document& model) {
  json& buffers = model.doc["buffers"];
  if (!buffers.is_array()) buffers = json::array();
  if (!buffers.empty() && !member(buffers[0], "uri").is_string()) return;
  for (json& view : model.doc["bufferViews"]) {
    if (view.is_object()) view["buffer"] = index_or(member(view, "buffer"), 0) + 1;
  }
  buffers.insert(buffers.begin(), json{{"byteLength", 0}});
  model.bin.clear();
}

// Node name → index, for names held by exactly one node.
std::map<std::string, int> nodes_by_name(const json& doc) {
  std::map<std::string, int> names;
  std::set<std::string> repeated;
  const json& nodes = member(doc, "nodes");
  for (std::size_t i = 0; i < (nodes.is_array() ? nodes.size() : 0); ++i) {
    const json& name = member(nodes[i], "name");
    if (!name.is_string()) continue;
    if (!names.emplace(name.get<std::string>(), static_cast<int>(i)).second) repeated.insert(name.get<std::string>());
  }
  for (const std::string& name : repeated) names.erase(name);
  return names;
}

// A node a clip moves has its rest transform as translation, rotation and
// scale (glTF 2.0 §3.7.3.1: an animated node has no matrix); assimp writes
// every node's transform as a matrix, which is taken apart here.
void make_movable(json& node) {
  const json& matrix = member(node, "matrix");
  if (!matrix.is_array() || matrix.size() != 16) return;
  glm::dmat4 m(1.0);
  for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = number_or(matrix[static_cast<std::size_t>(i)], i % 5 == 0 ? 1.0 : 0.0);
  glm::dvec3 scale;
  glm::dquat rotation;
  glm::dvec3 translation;
  glm::dvec3 skew;
  glm::dvec4 perspective;
  if (!glm::decompose(m, scale, rotation, translation, skew, perspective)) return;
  node.erase("matrix");
  node["translation"] = {translation.x, translation.y, translation.z};
  node["rotation"] = {rotation.x, rotation.y, rotation.z, rotation.w};
  node["scale"] = {scale.x, scale.y, scale.z};
}

std::string node_name(const json& doc, int node) {
  const json& name = member(element(member(doc, "nodes"), static_cast<std::size_t>(std::max(node, 0))), "name");
  return name.is_string() ? name.get<std::string>() : "node " + std::to_string(node);
}

std::string clip_label(const json& animation, std::size_t index) {
  const json& name = member(animation, "name");
  return "'" +
         (name.is_string() && !name.get<std::string>().empty() ? name.get<std::string>()
                                                               : "animation " + std::to_string(index)) +
         "'";
}

}  // namespace

MergedClips merge_clips(std::string_view model_bytes, const std::string& model_path, std::string_view clip_bytes,
                        const std::string& clips_path, const BufferFiles& clip_buffers,
                        std::vector<std::string>& warnings) {
  Document model = parse(model_bytes, model_path);
  const Document clips = parse(clip_bytes, clips_path);
  make_binary_buffer(model);
  AccessorCopier copier(model, 0, clips, clips_path, clip_buffers);
  const std::map<std::string, int> model_nodes = nodes_by_name(model.doc);
  MergedClips merged;
  const json& animations = member(clips.doc, "animations");
  for (std::size_t a = 0; a < (animations.is_array() ? animations.size() : 0); ++a) {
    const json& animation = animations[a];
    std::set<std::string> missing;
    json channels = json::array();
    json samplers = json::array();
    std::map<int, int> sampler_of;
    const json& source_samplers = member(animation, "samplers");
    for (const json& channel : member(animation, "channels")) {
      const json& target = member(channel, "target");
      if (member(target, "path") == "weights") continue;  // morph weights belong to the clip file's meshes
      const std::string name = node_name(clips.doc, index_or(member(target, "node"), -1));
      const auto node = model_nodes.find(name);
      if (node == model_nodes.end()) {
        missing.insert(name);
        continue;
      }
      const int sampler = index_or(member(channel, "sampler"), -1);
      const json& source = element(source_samplers, static_cast<std::size_t>(std::max(sampler, 0)));
      if (sampler < 0 || !source.is_object()) throw ImportError(clips_path, clips_path + ": a channel has no sampler");
      if (!sampler_of.contains(sampler)) {
        json copy = source;
        copy["input"] = copier.copy(index_or(member(source, "input"), -1));
        copy["output"] = copier.copy(index_or(member(source, "output"), -1));
        samplers.push_back(std::move(copy));
        sampler_of[sampler] = static_cast<int>(samplers.size()) - 1;
      }
      make_movable(model.doc["nodes"][static_cast<std::size_t>(node->second)]);
      channels.push_back(
          {{"sampler", sampler_of[sampler]}, {"target", {{"node", node->second}, {"path", target["path"]}}}});
    }
    if (!missing.empty() || channels.empty()) {
      std::string names;
      std::size_t shown = 0;
      for (const std::string& name : missing) {
        if (shown++ == 6) {
          names += ", ...";
          break;
        }
        names += (names.empty() ? "'" : ", '") + name + "'";
      }
      warnings.push_back(clips_path + ": clip " + clip_label(animation, a) + " is left out: " +
                         (missing.empty() ? std::string("it moves nothing")
                                          : "the model has no joint named " + names + " (" +
                                                std::to_string(missing.size()) + " of its joints)"));
      continue;
    }
    json added = {{"samplers", samplers}, {"channels", channels}};
    added["name"] = clip_label(animation, a).substr(1, clip_label(animation, a).size() - 2);
    model.doc["animations"].push_back(std::move(added));
    merged.added.push_back(a);
  }
  model.doc["buffers"][0]["byteLength"] = model.bin.size();
  merged.gltf = glb::glb_container(model.doc.dump(-1, ' ', false, json::error_handler_t::replace), model.bin);
  return merged;
}

std::optional<GltfContents> gltf_contents(std::string_view bytes) {
  if (!looks_like_gltf(bytes)) return std::nullopt;
  try {
    const Document d = parse(bytes, "");
    GltfContents contents;
    const json& meshes = member(d.doc, "meshes");
    contents.meshes = meshes.is_array() && !meshes.empty();
    std::set<int> moved;
    const json& animations = member(d.doc, "animations");
    for (std::size_t a = 0; a < (animations.is_array() ? animations.size() : 0); ++a) {
      const std::string label = clip_label(animations[a], a);
      contents.clips.push_back(label.substr(1, label.size() - 2));
      for (const json& channel : member(animations[a], "channels")) {
        moved.insert(index_or(member(member(channel, "target"), "node"), -1));
      }
    }
    contents.nodes = moved.size();
    return contents;
  } catch (const ImportError&) {
    return std::nullopt;
  }
}

}  // namespace toond::scene
