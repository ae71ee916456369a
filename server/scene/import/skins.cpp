#include "scene/import/skins.h"

#include <algorithm>
#include <optional>
#include <set>

#include "bundle_paths/bundle_path.h"
#include "bundle_paths/name_index.h"
#include "scene/import/assimp_import.h"
#include "scene/import/bundle_import.h"
#include "scene/reading/image_lookup.h"
#include "scene/reading/import_error.h"
#include "scene/reading/texture_decode.h"
#include "text/trim.h"

namespace toond::scene {
namespace {

constexpr std::string_view kTexturesField = "?textures";

std::string skin_quoted(std::string_view s) { return "'" + std::string(s) + "'"; }

std::string skin_listing(const std::vector<std::string>& names, std::size_t most = 8) {
  std::string text;
  for (std::size_t i = 0; i < names.size() && i < most; ++i) text += (i ? ", " : "") + skin_quoted(names[i]);
  if (names.size() > most) text += ", ...";
  return text;
}

std::vector<std::string> material_names(const Model& model) {
  std::vector<std::string> names;
  for (const Material& m : model.materials) names.push_back(m.name);
  return names;
}

bool is_game_format(std::string_view path) { return read_through_assimp(path) || has_extension(path, ".iqm"); }

// The model's textures of bundle images as colour maps, each decoded once
// and within what the model's other textures left of kModelTexturePixels.
class SkinTextures {
 public:
  SkinTextures(Model& model, const Bundle& bundle, const ImportLimits& limits)
      : model_(model), bundle_(bundle), limits_(limits) {
    for (const Texture& t : model.textures) pixels_left_ -= std::min<std::uint64_t>(pixels_left_, pixels(t));
  }

  // The slot of image `path`, or -1 with `why` set when it does not decode.
  int slot_of(const std::string& path, std::string& why) {
    for (std::size_t i = 0; i < model_.textures.size(); ++i) {
      const Texture& t = model_.textures[i];
      if (t.path == path && t.color_space == ColorSpace::Srgb) return static_cast<int>(i);
    }
    try {
      Texture texture = decode_model_texture(*bundle_.find(path), path, limits_.max_texture_pixels, pixels_left_);
      texture.color_space = ColorSpace::Srgb;
      model_.textures.push_back(std::move(texture));
      return static_cast<int>(model_.textures.size()) - 1;
    } catch (const ImportLimitError&) {
      throw;
    } catch (const std::exception& e) {
      why = e.what();
      return -1;
    }
  }

 private:
  static std::uint64_t pixels(const Texture& t) {
    return static_cast<std::uint64_t>(t.width) * static_cast<std::uint64_t>(t.height);
  }
  Model& model_;
  const Bundle& bundle_;
  ImportLimits limits_;
  std::uint64_t pixels_left_ = kModelTexturePixels;
};

void put_image(Material& material, int slot) {
  material.diffuse_texture = slot;
  material.diffuse = glm::vec3(1.0f);
}

// The materials a "material:image" entry's name picks: those of that name,
// else those of that name in another case.
std::vector<std::size_t> materials_named(const Model& model, std::string_view name) {
  std::vector<std::size_t> exact;
  std::vector<std::size_t> folded;
  for (std::size_t i = 0; i < model.materials.size(); ++i) {
    if (model.materials[i].name == name) exact.push_back(i);
    if (bundle_paths::same_ignoring_case(model.materials[i].name, name)) folded.push_back(i);
  }
  return exact.empty() ? folded : exact;
}

void put_listed_skins(Model& model, const Bundle& bundle, const std::string& path, const ImportChoices& choices,
                      SkinTextures& textures) {
  const std::vector<std::string>& entries = choices.textures;
  const bool by_name = std::any_of(entries.begin(), entries.end(),
                                   [](const std::string& e) { return e.find(':') != std::string::npos; });
  if (!by_name && entries.size() > model.materials.size()) {
    throw ImportError(std::string(kTexturesField), std::string(kTexturesField) + ": " + std::to_string(entries.size()) +
                                                       " images for " + std::to_string(model.materials.size()) +
                                                       " materials (" + skin_listing(material_names(model)) +
                                                       "); list at most one image per material, in that order");
  }
  for (std::size_t i = 0; i < entries.size(); ++i) {
    std::string image = entries[i];
    std::vector<std::size_t> targets = {i};
    if (const std::size_t colon = image.find(':'); colon != std::string::npos) {
      const std::string name = image.substr(0, colon);
      image = image.substr(colon + 1);
      targets = materials_named(model, name);
      if (targets.empty()) {
        throw ImportError(std::string(kTexturesField), std::string(kTexturesField) + ": the model has no material " +
                                                           skin_quoted(name) + "; its materials are " +
                                                           skin_listing(material_names(model)));
      }
    } else if (by_name) {
      throw ImportError(std::string(kTexturesField),
                        std::string(kTexturesField) + ": " + skin_quoted(image) +
                            " names no material; once one entry is \"material:image\", every entry must be");
    }
    if (image.empty()) continue;
    const auto found = find_image(bundle, path, image);
    if (!found) {
      throw ImportError(std::string(kTexturesField),
                        std::string(kTexturesField) + ": " + skin_quoted(image) + " is not in the upload");
    }
    std::string why;
    const int slot = textures.slot_of(found->path, why);
    if (slot < 0) {
      throw ImportError(std::string(kTexturesField), std::string(kTexturesField) + ": " + skin_quoted(found->path) +
                                                         " is not a readable image: " + why);
    }
    for (const std::size_t m : targets) put_image(model.materials[m], slot);
  }
}

std::set<std::string> used_images(const Model& model) {
  std::set<std::string> used;
  for (const Texture& t : model.textures) used.insert(t.path);
  return used;
}

// The upload's one image no material uses, as every material's skin, where
// no material has one.
void put_lone_image(Model& model, const Bundle& bundle, const std::string& path, SkinTextures& textures) {
  for (const Material& material : model.materials) {
    if (material.diffuse_texture >= 0) return;
  }
  // Without texture coordinates an image would paint one texel's colour.
  const auto& uv = model.mesh.texcoords;
  if (std::all_of(uv.begin(), uv.end(), [](const glm::vec2& t) { return t == glm::vec2(0.0f); })) return;
  const std::set<std::string> used = used_images(model);
  std::vector<std::string> unused;
  for (const std::string& image : bundle_images(bundle)) {
    if (!used.contains(image)) unused.push_back(image);
  }
  if (unused.size() != 1) return;
  std::string why;
  const int slot = textures.slot_of(unused.front(), why);
  if (slot < 0) return;  // not an image after all: the file was sent for something else
  for (Material& material : model.materials) put_image(material, slot);
  model.warnings.push_back(path + ": names no texture it could be drawn with; drawn with " +
                           skin_quoted(unused.front()) + ", the upload's one image, as a game gives a model its skin");
}

// The `.skin` file of MD3 model `path`: `<name>_default.skin` beside it, else
// the one `<name>_*.skin`, else the upload's one `.skin`.
std::optional<std::string> skin_file_of(const Bundle& bundle, const std::string& path) {
  const std::string_view folder = bundle_paths::folder_of(path);
  const std::string stem = path.substr(0, path.size() - 4);  // less ".md3"
  std::vector<std::string> named;
  std::vector<std::string> any;
  for (const auto& [file, content] : bundle.files()) {
    if (!has_extension(file, ".skin")) continue;
    any.push_back(file);
    if (bundle_paths::same_ignoring_case(file, stem + "_default.skin")) return file;
    if (bundle_paths::folder_of(file) == folder &&
        bundle_paths::case_folded(file).starts_with(bundle_paths::case_folded(stem) + "_"))
      named.push_back(file);
  }
  if (named.size() == 1) return named.front();
  if (named.empty() && any.size() == 1) return any.front();
  return std::nullopt;
}

// A Quake 3 `.skin` file's `surface,image` lines, each image on the
// material of that surface (tags, with no image, are skipped).
void put_skin_file(Model& model, const Bundle& bundle, const std::string& path, SkinTextures& textures) {
  if (!has_extension(path, ".md3")) return;
  const auto skin = skin_file_of(bundle, path);
  if (!skin) return;
  const std::string& text = *bundle.find(*skin);
  std::size_t at = 0;
  while (at < text.size()) {
    const std::size_t end = std::min(text.find_first_of("\r\n", at), text.size());
    const std::string line = text.substr(at, end - at);
    at = end + 1;
    const std::size_t comma = line.find(',');
    if (comma == std::string::npos) continue;
    const std::string surface(text::trim(std::string_view(line).substr(0, comma)));
    const std::string image(text::trim(std::string_view(line).substr(comma + 1)));
    if (surface.empty() || image.empty()) continue;
    const std::vector<std::size_t> targets = materials_named(model, surface);
    if (targets.empty()) continue;
    const auto found = find_image(bundle, *skin, image);
    std::string why = "it is not in the upload";
    const int slot = found ? textures.slot_of(found->path, why) : -1;
    if (slot < 0) {
      model.warnings.push_back(*skin + ": the image " + skin_quoted(image) + " of surface " + skin_quoted(surface) +
                               " cannot be used: " + why);
      continue;
    }
    for (const std::size_t m : targets) put_image(model.materials[m], slot);
  }
}

}  // namespace

AlphaMode alpha_of_image(const Texture& image) {
  if (image.min_alpha == 255) return AlphaMode::Opaque;
  return image.min_alpha == 0 ? AlphaMode::Mask : AlphaMode::Blend;
}

bool skins_left_to_game(const Bundle& bundle, std::string_view path) {
  if (is_game_format(path)) return true;
  if (!has_extension(path, ".obj")) return false;
  return std::none_of(bundle.files().begin(), bundle.files().end(),
                      [](const auto& file) { return has_extension(file.first, ".mtl"); });
}

void put_skins(Model& model, const Bundle& bundle, const std::string& path, const ImportChoices& choices,
               const ImportLimits& limits) {
  SkinTextures textures(model, bundle, limits);
  put_skin_file(model, bundle, path, textures);
  put_listed_skins(model, bundle, path, choices, textures);
  if (skins_left_to_game(bundle, path)) put_lone_image(model, bundle, path, textures);
}

void apply_format_conventions(Model& model, std::string_view path) {
  if (has_extension(path, ".obj")) {
    // A colour image with alpha cuts its shape out, whether the MTL named
    // it or the upload put it there (obj_import.h reads the MTL's own word).
    for (Material& material : model.materials) {
      if (material.alpha_mode != AlphaMode::Opaque || material.diffuse_texture < 0) continue;
      material.alpha_mode = alpha_of_image(model.textures[static_cast<std::size_t>(material.diffuse_texture)]);
    }
    return;
  }
  const bool irrlicht = has_extension(path, ".b3d");
  const bool quake = has_extension(path, ".md2") || has_extension(path, ".md3");
  const bool cube2 = has_extension(path, ".iqm") || has_extension(path, ".md5mesh");
  if (!irrlicht && !quake && !cube2) return;
  for (Material& material : model.materials) {
    // Their files carry no highlight a game draws.
    material.matte = true;
    if (material.diffuse_texture < 0) continue;
    if (irrlicht) material.diffuse = glm::vec3(1.0f);
    if (quake) {
      material.alpha_mode = AlphaMode::Opaque;
    } else if (material.alpha_mode == AlphaMode::Opaque) {
      material.alpha_mode = AlphaMode::Mask;
      material.alpha_cutoff = irrlicht ? 0.5f : 0.9f;
    }
  }
}

void warn_unused_images(Model& model, const Bundle& bundle) {
  const std::set<std::string> used = used_images(model);
  std::vector<std::string> unused;
  for (const std::string& image : bundle_images(bundle)) {
    if (!used.contains(image)) unused.push_back(image);
  }
  if (unused.empty()) return;
  model.warnings.push_back(
      std::string(unused.size() == 1 ? "no material uses the image " : "no material uses the images ") +
      skin_listing(unused) +
      "; to draw one, name it in ?textures= (images in material order: " + skin_listing(material_names(model)) +
      ", or \"material:image\"), or per request as materials.<name>.texture, "
      "shading.ramp_image or floor.texture");
}

}  // namespace toond::scene
