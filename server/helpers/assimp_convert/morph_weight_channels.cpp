#include "helpers/assimp_convert/morph_weight_channels.h"

#include <algorithm>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "glb/glb_container.h"

namespace toond::assimp_convert {
namespace {

using nlohmann::json;

constexpr int kFloat = 5126;

bool has_morph_channels(const aiScene& scene) {
  for (unsigned a = 0; a < scene.mNumAnimations; ++a) {
    if (scene.mAnimations[a]->mNumMorphMeshChannels > 0) return true;
  }
  return false;
}

// The nodes in the order the glTF writer numbers them: the root, then each
// child's subtree in turn.
void nodes_in_written_order(const aiNode& node, std::vector<const aiNode*>& order) {
  order.push_back(&node);
  for (unsigned c = 0; c < node.mNumChildren; ++c) nodes_in_written_order(*node.mChildren[c], order);
}

// The mesh a morph channel names: assimp writes "<mesh name>*<index>".
std::string mesh_name_of(const aiMeshMorphAnim& channel) {
  const std::string name = channel.mName.C_Str();
  return name.substr(0, name.rfind('*'));
}

bool draws_mesh_named(const aiScene& scene, const aiNode& node, const std::string& mesh) {
  for (unsigned m = 0; m < node.mNumMeshes; ++m) {
    if (scene.mMeshes[node.mMeshes[m]]->mName.C_Str() == mesh) return true;
  }
  return false;
}

class GlbAppender {
 public:
  GlbAppender(json& doc, std::string& bin) : doc_(doc), bin_(bin) {}

  // A SCALAR float accessor of `values` (with its bounds, which glTF asks
  // of a clip's key times).
  int scalars(const std::vector<float>& values, bool with_bounds) {
    while (bin_.size() % 4) bin_.push_back('\0');
    const std::size_t offset = bin_.size();
    bin_.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(float));
    doc_["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * 4}});
    json accessor = {{"bufferView", doc_["bufferViews"].size() - 1},
                     {"componentType", kFloat},
                     {"count", values.size()},
                     {"type", "SCALAR"}};
    if (with_bounds && !values.empty()) {
      accessor["min"] = {*std::min_element(values.begin(), values.end())};
      accessor["max"] = {*std::max_element(values.begin(), values.end())};
    }
    doc_["accessors"].push_back(std::move(accessor));
    return static_cast<int>(doc_["accessors"].size() - 1);
  }

  void finish() {
    while (bin_.size() % 4) bin_.push_back('\0');
    doc_["buffers"][0]["byteLength"] = bin_.size();
  }

 private:
  json& doc_;
  std::string& bin_;
};

json& animation_named(json& doc, unsigned index, const std::string& name) {
  json& animations = doc["animations"];
  if (!animations.is_array()) animations = json::array();
  if (index < animations.size() && animations[index].value("name", "") == name) return animations[index];
  for (json& animation : animations) {
    if (animation.value("name", "") == name) return animation;
  }
  animations.push_back({{"name", name}, {"channels", json::array()}, {"samplers", json::array()}});
  return animations.back();
}

// The number of morph targets every primitive of glTF mesh `mesh` has, or
// 0 when they differ or there are none.
std::size_t target_count(const json& doc, const json& mesh_index) {
  if (!mesh_index.is_number_unsigned() || mesh_index.get<std::size_t>() >= doc["meshes"].size()) return 0;
  std::size_t count = 0;
  bool first = true;
  for (const json& primitive : doc["meshes"][mesh_index.get<std::size_t>()]["primitives"]) {
    const std::size_t here = primitive.contains("targets") ? primitive["targets"].size() : 0;
    if (!first && here != count) return 0;
    count = here;
    first = false;
  }
  return count;
}

void add_channel(GlbAppender& append, json& animation, std::size_t node, std::size_t targets,
                 const aiMeshMorphAnim& channel, double ticks_per_second) {
  std::vector<float> times(channel.mNumKeys);
  std::vector<float> weights(std::size_t{channel.mNumKeys} * targets, 0.0f);
  for (unsigned k = 0; k < channel.mNumKeys; ++k) {
    const aiMeshMorphKey& key = channel.mKeys[k];
    times[k] = static_cast<float>(key.mTime / ticks_per_second);
    for (unsigned v = 0; v < key.mNumValuesAndWeights; ++v) {
      if (key.mValues[v] < targets) weights[k * targets + key.mValues[v]] = static_cast<float>(key.mWeights[v]);
    }
  }
  const int input = append.scalars(times, true);
  const int output = append.scalars(weights, false);
  animation["samplers"].push_back({{"input", input}, {"output", output}, {"interpolation", "LINEAR"}});
  animation["channels"].push_back(
      {{"sampler", animation["samplers"].size() - 1}, {"target", {{"node", node}, {"path", "weights"}}}});
}

}  // namespace

std::string with_morph_weight_channels(const std::string& glb, const aiScene& scene, std::vector<std::string>& notes) {
  if (!has_morph_channels(scene)) return glb;
  const auto chunks = glb::glb_chunks(glb);
  if (!chunks) throw std::runtime_error("assimp's glTF answer is not a well-formed container");
  json doc = json::parse(chunks->json);
  std::string bin(chunks->bin);
  GlbAppender append(doc, bin);
  std::vector<const aiNode*> order;
  nodes_in_written_order(*scene.mRootNode, order);
  const bool numbered_as_written = doc["nodes"].is_array() && doc["nodes"].size() == order.size();

  for (unsigned a = 0; a < scene.mNumAnimations; ++a) {
    const aiAnimation& clip = *scene.mAnimations[a];
    const double ticks_per_second = clip.mTicksPerSecond > 0 ? clip.mTicksPerSecond : 1.0;
    for (unsigned c = 0; c < clip.mNumMorphMeshChannels; ++c) {
      const aiMeshMorphAnim& channel = *clip.mMorphMeshChannels[c];
      const std::string mesh = mesh_name_of(channel);
      bool carried = false;
      for (std::size_t n = 0; numbered_as_written && n < order.size(); ++n) {
        if (!draws_mesh_named(scene, *order[n], mesh)) continue;
        const json& written = doc["nodes"][n];
        const std::size_t targets = target_count(doc, written.value("mesh", json()));
        if (targets == 0 || written.value("name", "") != order[n]->mName.C_Str()) continue;
        add_channel(append, animation_named(doc, a, clip.mName.C_Str()), n, targets, channel, ticks_per_second);
        carried = true;
      }
      if (!carried) {
        notes.push_back("the morph-target animation of mesh '" + mesh + "' in clip '" + clip.mName.C_Str() +
                        "' not read");
      }
    }
  }
  append.finish();
  return glb::glb_container(doc.dump(), bin);
}

}  // namespace toond::assimp_convert
