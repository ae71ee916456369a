// What the store says of a model (ModelInfo, as JSON), and its id.
#include "scene/store/model_store.h"

#include <cstdio>

#include <openssl/evp.h>

#include <algorithm>
#include <memory>
#include <stdexcept>

#include "scene/import/bundle_import.h"

namespace toond::scene {
using namespace std::string_view_literals;
namespace {

constexpr std::size_t kIdLength = 32;

// The up axis a stored model was imported with. Models stored before the
// format's convention was the default say "up" only when it was `z`;
// without it they were read Y-up, but for 3MF, which the assimp helper then
// turned itself.
ImportChoices::Up stored_up(const nlohmann::json& j, const std::vector<std::string>& files) {
  if (const auto up = j.find("up"); up != j.end() && up->is_string()) {
    return *up == "z" ? ImportChoices::Up::Z : ImportChoices::Up::Y;
  }
  const bool three_mf =
      std::any_of(files.begin(), files.end(), [](const std::string& file) { return has_extension(file, ".3mf"); });
  return three_mf ? ImportChoices::Up::Z : ImportChoices::Up::Y;
}

const char* alpha_name(AlphaMode mode) {
  switch (mode) {
    case AlphaMode::Mask:
      return "mask";
    case AlphaMode::Blend:
      return "blend";
    case AlphaMode::Opaque:
      break;
  }
  return "opaque";
}

}  // namespace

std::vector<ModelInfo::MaterialEntry> material_entries(const Model& model) {
  std::vector<ModelInfo::MaterialEntry> entries;
  for (const Material& m : model.materials) {
    const bool textured = m.diffuse_texture >= 0 && static_cast<std::size_t>(m.diffuse_texture) < model.textures.size();
    entries.push_back({m.name, textured ? model.textures[static_cast<std::size_t>(m.diffuse_texture)].path : "",
                       alpha_name(m.alpha_mode), m.alpha_cutoff, m.matte});
  }
  return entries;
}

nlohmann::json ModelInfo::to_json() const {
  nlohmann::json j = {{"id", id},
                      {"triangles", triangles},
                      {"materials", materials},
                      {"textures", textures},
                      {"bytes", bytes},
                      {"files", files},
                      {"warnings", warnings},
                      {"weld", {{"tolerance", weld.tolerance}, {"positions", weld.positions}}},
                      {"cost", {{"layers", cost.layers}, {"edge_span", cost.edge_span}}}};
  if (animation.any()) {
    nlohmann::json clips = nlohmann::json::array();
    for (const ClipInfo& c : animation.clips) {
      nlohmann::json clip = {{"name", c.name}, {"duration", c.duration}, {"channels", c.channels}};
      if (c.frame_rate) clip["frame_rate"] = *c.frame_rate;
      clips.push_back(std::move(clip));
    }
    j["animation"] = {{"clips", clips}, {"joints", animation.joints}, {"morph_targets", animation.morph_targets}};
  }
  if (choices.gltf_scene) j["scene"] = *choices.gltf_scene;
  if (choices.smooth_angle) j["smooth_angle"] = *choices.smooth_angle;
  if (choices.up != ImportChoices::Up::FormatDefault) j["up"] = choices.z_up() ? "z" : "y";
  if (!choices.textures.empty()) j["texture_map"] = choices.textures;
  if (!material_list.empty()) {
    nlohmann::json list = nlohmann::json::array();
    for (const MaterialEntry& m : material_list) {
      list.push_back({{"name", m.name},
                      {"texture", m.texture},
                      {"alpha", m.alpha},
                      {"alpha_cutoff", m.alpha_cutoff},
                      {"matte", m.matte}});
    }
    j["material_list"] = std::move(list);
  }
  return j;
}

ModelInfo ModelInfo::from_json(const nlohmann::json& j) {
  ModelInfo info;
  info.id = j.at("id").get<std::string>();
  info.triangles = j.at("triangles").get<std::size_t>();
  info.materials = j.at("materials").get<std::size_t>();
  info.textures = j.at("textures").get<std::size_t>();
  info.bytes = j.at("bytes").get<std::size_t>();
  info.files = j.at("files").get<std::vector<std::string>>();
  info.warnings = j.value("warnings", std::vector<std::string>{});
  // Models stored before their cost was measured have no record of it.
  if (const auto cost = j.find("cost"); cost != j.end() && cost->is_object()) {
    info.cost.layers = cost->value("layers", 0.0);
    info.cost.edge_span = cost->value("edge_span", 0.0);
  }
  // Models stored before welding was reported have no record of it.
  if (const auto weld = j.find("weld"); weld != j.end() && weld->is_object()) {
    info.weld.tolerance = weld->value("tolerance", 0.0);
    info.weld.positions = weld->value("positions", std::size_t{0});
  }
  if (const auto animation = j.find("animation"); animation != j.end() && animation->is_object()) {
    for (const nlohmann::json& c : animation->value("clips", nlohmann::json::array())) {
      ClipInfo clip{c.value("name", std::string()), c.value("duration", 0.0), c.value("channels", std::size_t{0}), {}};
      if (const auto rate = c.find("frame_rate"); rate != c.end() && rate->is_number())
        clip.frame_rate = rate->get<double>();
      info.animation.clips.push_back(std::move(clip));
    }
    info.animation.joints = animation->value("joints", std::size_t{0});
    info.animation.morph_targets = animation->value("morph_targets", std::size_t{0});
  }
  if (const auto scene = j.find("scene"); scene != j.end() && scene->is_number_integer()) {
    info.choices.gltf_scene = scene->get<int>();
  }
  if (const auto angle = j.find("smooth_angle"); angle != j.end() && angle->is_number()) {
    info.choices.smooth_angle = angle->get<double>();
  }
  info.choices.up = stored_up(j, info.files);
  if (const auto textures = j.find("texture_map"); textures != j.end() && textures->is_array()) {
    for (const nlohmann::json& entry : *textures) {
      if (entry.is_string()) info.choices.textures.push_back(entry.get<std::string>());
    }
  }
  if (const auto list = j.find("material_list"); list != j.end() && list->is_array()) {
    for (const nlohmann::json& m : *list) {
      if (!m.is_object()) continue;
      info.material_list.push_back({m.value("name", std::string()), m.value("texture", std::string()),
                                    m.value("alpha", std::string("opaque")), m.value("alpha_cutoff", 0.5),
                                    m.value("matte", false)});
    }
  }
  return info;
}

std::string bundle_id(const Bundle& bundle, const ImportChoices& choices) {
  std::unique_ptr<EVP_MD_CTX, void (*)(EVP_MD_CTX*)> ctx(EVP_MD_CTX_new(), EVP_MD_CTX_free);
  if (!ctx || EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) != 1) {
    throw std::runtime_error("SHA-256 is not available");
  }
  const auto feed = [&](std::string_view bytes) {
    if (EVP_DigestUpdate(ctx.get(), bytes.data(), bytes.size()) != 1) throw std::runtime_error("SHA-256 failed");
  };
  // Sizes and separators keep the records unambiguous: no two different
  // bundles produce the same byte stream.
  for (const auto& [path, content] : bundle.files()) {
    feed(path);
    feed(std::string_view("\0", 1));
    feed(std::to_string(content.size()));
    feed(std::string_view("\0", 1));
    feed(content);
  }
  // No path holds a NUL, so this record cannot be taken for a file's.
  if (choices.gltf_scene) {
    feed(std::string_view("\0scene\0", 7));
    feed(std::to_string(*choices.gltf_scene));
  }
  if (choices.smooth_angle) {
    char angle[32];
    std::snprintf(angle, sizeof angle, "%.17g", *choices.smooth_angle);
    feed("\0smooth_angle\0"sv);
    feed(angle);
  }
  if (choices.z_up()) feed("\0up\0z"sv);
  // Entries hold no NUL either: each is cut off by one.
  if (!choices.textures.empty()) {
    feed("\0textures\0"sv);
    for (const std::string& entry : choices.textures) {
      feed(entry);
      feed("\0"sv);
    }
  }
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (EVP_DigestFinal_ex(ctx.get(), digest, &length) != 1) throw std::runtime_error("SHA-256 failed");
  static constexpr char kHex[] = "0123456789abcdef";
  std::string id;
  for (unsigned int i = 0; i < length && id.size() < kIdLength; ++i) {
    id += kHex[digest[i] >> 4];
    id += kHex[digest[i] & 0xf];
  }
  return id;
}

}  // namespace toond::scene
