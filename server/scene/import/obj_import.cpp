#include "scene/import/obj_import.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <utility>
#include <vector>

#include "bundle_paths/statement_names.h"
#include "obj_text/mtl_material.h"
#include "obj_text/obj_text.h"
#include "scene/import/bundle_import.h"
#include "scene/import/skins.h"
#include "scene/reading/image_lookup.h"
#include "scene/reading/import_error.h"
#include "scene/reading/mesh_builder.h"
#include "scene/reading/texture_decode.h"
#include "text/trim.h"

namespace toond::scene {
namespace {

std::string quoted(std::string_view s) { return "'" + std::string(s) + "'"; }

std::string find_obj(const Bundle& bundle) { return find_model_file(bundle, {".obj"}, ".obj"); }

// Serves `mtllib` names from the bundle instead of the file system, and
// remembers which MTL each material came from: texture names in an MTL are
// relative to the MTL's own folder.
class BundleMaterialReader : public tinyobj::MaterialReader {
 public:
  BundleMaterialReader(const Bundle& bundle, std::string obj_path, ImportWarnings& warnings)
      : bundle_(bundle), obj_path_(std::move(obj_path)), warnings_(warnings) {}

  // `line` is a whole mtllib line (prepare_obj_text keeps tinyobj from
  // cutting it), read as toon reads it.
  bool operator()(const std::string& line, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* material_map, std::string*, std::string*) override {
    const auto in_bundle = [&](const std::string& name) { return bundle_.resolve(obj_path_, name).has_value(); };
    for (const std::string& reference : bundle_paths::mtllib_names(line, in_bundle)) {
      load(reference, materials, material_map);
    }
    // Missing libraries are said by load, precisely: answering "found" keeps
    // tinyobj from adding a warning of its own.
    return true;
  }

  // What the MTL says of material `id` (tinyobj's numbering).
  const obj_text::MtlMaterial& material(int id) const { return said_.at(static_cast<std::size_t>(id)); }

  // The MTL that defined material `id` (the OBJ itself when unknown).
  const std::string& source_of(int id) const {
    return id >= 0 && static_cast<std::size_t>(id) < sources_.size() ? sources_[static_cast<std::size_t>(id)]
                                                                     : obj_path_;
  }

 private:
  // The materials of library `reference`, added to tinyobj's lists.
  void load(const std::string& reference, std::vector<tinyobj::material_t>* materials,
            std::map<std::string, int>* material_map) {
    const auto path = bundle_.resolve(obj_path_, reference);
    if (!path) {
      warnings_.add(obj_path_ + ": material library " + quoted(reference) +
                    " is not in the bundle; its materials fall back to the default colour");
      return;
    }
    std::string warn;
    std::string err;
    std::vector<obj_text::MtlMaterial> said =
        obj_text::read_mtl(*bundle_.find(*path), materials, material_map, &warn, &err);
    for (const std::string* text : {&warn, &err}) {
      std::istringstream lines(*text);
      for (std::string line; std::getline(lines, line);) {
        line = std::string(text::trim(line));
        if (!line.empty() && line != ".") warnings_.add(*path + ": " + line);
      }
    }
    sources_.resize(materials->size(), *path);
    std::move(said.begin(), said.end(), std::back_inserter(said_));
  }

  const Bundle& bundle_;
  std::string obj_path_;
  ImportWarnings& warnings_;
  std::vector<std::string> sources_;
  std::vector<obj_text::MtlMaterial> said_;  // per material, in tinyobj's order
};

// Only consulted on failure, so the common path does not scan the text twice.
std::size_t line_of_vertex(const std::string& text, std::size_t vertex) {
  std::size_t line = 0;
  std::size_t seen = 0;
  std::istringstream in(text);
  for (std::string s; std::getline(in, s);) {
    ++line;
    const auto first = s.find_first_not_of(" \t");
    if (first != std::string::npos && s[first] == 'v' && first + 1 < s.size() &&
        (s[first + 1] == ' ' || s[first + 1] == '\t')) {
      if (seen++ == vertex) return line;
    }
  }
  return 0;
}

glm::vec3 vec3_of(const obj_text::Rgb& rgb) { return {rgb[0], rgb[1], rgb[2]}; }

// An image whose every pixel is grey is a height map (the classic meaning
// of `bump`), not a tangent-space normal map, whose texels lean blue.
bool is_greyscale(const Texture& texture) {
  for (std::size_t i = 0; i + 3 < texture.rgba.size(); i += 4) {
    if (texture.rgba[i] != texture.rgba[i + 1] || texture.rgba[i] != texture.rgba[i + 2]) return false;
  }
  return true;
}

class Importer {
 public:
  Importer(const Bundle& bundle, const ImportLimits& limits, const ImportChoices& choices)
      : bundle_(bundle), obj_path_(find_obj(bundle)), limits_(limits), choices_(choices) {}

  Model run() {
    parse();
    check_import_time(limits_, "parsing " + obj_path_);
    MeshSource source = make_source();
    source.limits = limits_;
    apply_import_choices(source, choices_);
    model_.mesh = build_mesh(source, warnings_, [this](std::vector<SourceTriangle>& triangles) {
      build_materials(triangles);
      check_import_time(limits_, "decoding textures");
    });
    model_.has_vertex_colors = !model_.mesh.colors.empty();
    model_.warnings = warnings_.take();
    return std::move(model_);
  }

 private:
  void parse() {
    obj_text::ObjTextFindings findings;
    std::istringstream in(obj_text::prepare_obj_text(*bundle_.find(obj_path_), &findings));
    // tinyobj drops a quad naming a missing vertex without a word; a model
    // with holes is worse than a clear refusal.
    if (findings.missing_vertex_line != 0) {
      throw ImportError(obj_path_, obj_path_ + ": a face refers to a vertex that does not exist (line " +
                                       std::to_string(findings.missing_vertex_line) + ")");
    }
    std::string warn;
    std::string err;
    reader_ = std::make_unique<BundleMaterialReader>(bundle_, obj_path_, warnings_);
    // Without the fallback, attrib.colors is empty unless every `v` line
    // carries a colour (tinyobj would otherwise fill in white).
    const bool ok = tinyobj::LoadObj(&attrib_, &shapes_, &tinyobj_materials_, &warn, &err, &in, reader_.get(),
                                     /*triangulate=*/true, /*default_vcols_fallback=*/false);
    if (!ok) {
      std::string reason(text::trim(std::string_view(err).substr(0, err.find('\n'))));
      if (reason.empty()) reason = "the parser gave no reason";
      throw ImportError(obj_path_, "cannot read " + obj_path_ + ": " + reason);
    }
    for (const std::string* messages : {&warn, &err}) {
      std::istringstream lines(*messages);
      for (std::string line; std::getline(lines, line);) {
        line = std::string(text::trim(line));
        if (line.empty() || line == ".") continue;
        std::replace(line.begin(), line.end(), '\x1f', ' ');  // undo material_alias for display
        warnings_.add(obj_path_ + ": " + line);
      }
    }
  }

  // tinyobj's lists and faces in the shared importer's terms; the lists are
  // moved out of attrib_, which is not used after.
  MeshSource make_source() {
    MeshSource source;
    source.file = obj_path_;
    const auto& v = attrib_.vertices;
    source.positions.reserve(v.size() / 3);
    for (std::size_t i = 0; i + 2 < v.size(); i += 3) source.positions.emplace_back(v[i], v[i + 1], v[i + 2]);
    const auto& vn = attrib_.normals;
    source.normals.reserve(vn.size() / 3);
    for (std::size_t i = 0; i + 2 < vn.size(); i += 3) source.normals.emplace_back(vn[i], vn[i + 1], vn[i + 2]);
    const auto& vt = attrib_.texcoords;
    source.texcoords.reserve(vt.size() / 2);
    for (std::size_t i = 0; i + 1 < vt.size(); i += 2) source.texcoords.emplace_back(vt[i], vt[i + 1]);
    const auto& vc = attrib_.colors;
    if (!vc.empty() && vc.size() == v.size()) {
      // OBJ's "v x y z r g b" extension: the file's 0..1 values, kept as
      // written (sRGB-encoded like picked colours; see Mesh::colors).
      source.colors.reserve(vc.size() / 3);
      for (std::size_t i = 0; i + 2 < vc.size(); i += 3) source.colors.emplace_back(vc[i], vc[i + 1], vc[i + 2]);
    }
    has_vertex_colors_ = !source.colors.empty();
    // Only called on failure, so the common path does not scan the text twice.
    source.describe_position = [this](std::size_t vertex) {
      const std::size_t line = line_of_vertex(*bundle_.find(obj_path_), vertex);
      return "vertex " + std::to_string(vertex + 1) + (line > 0 ? " (line " + std::to_string(line) + ")" : "");
    };
    attrib_ = tinyobj::attrib_t{};

    const auto position_count = static_cast<long long>(source.positions.size());
    std::size_t triangles = 0;  // reserved at once: grown one by one, a large file's list was copied over and over
    for (const auto& shape : shapes_) {
      for (const auto count : shape.mesh.num_face_vertices) triangles += count > 2 ? count - 2u : 0u;
    }
    source.triangles.reserve(triangles);
    for (const auto& shape : shapes_) {
      std::size_t offset = 0;
      for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
        const std::size_t count = shape.mesh.num_face_vertices[f];
        // LoadObj triangulates, but a fan keeps anything it leaves intact.
        for (std::size_t k = 1; k + 1 < count; ++k) {
          SourceTriangle tri;
          const std::size_t picks[3] = {offset, offset + k, offset + k + 1};
          for (int c = 0; c < 3; ++c) {
            const auto& idx = shape.mesh.indices[picks[c]];
            if (idx.vertex_index < 0 || idx.vertex_index >= position_count) {
              throw ImportError(obj_path_, obj_path_ + ": a face" +
                                               (shape.name.empty() ? "" : " in " + quoted(shape.name)) +
                                               " refers to a vertex position that does not exist (the file defines " +
                                               std::to_string(position_count) + ")");
            }
            SourceCorner& corner = tri.corner[c];
            corner.position = static_cast<std::uint32_t>(idx.vertex_index);
            corner.normal = idx.normal_index;
            corner.texcoord = idx.texcoord_index;
          }
          tri.material = f < shape.mesh.material_ids.size() ? shape.mesh.material_ids[f] : -1;
          tri.smoothing = f < shape.mesh.smoothing_group_ids.size() ? shape.mesh.smoothing_group_ids[f] : 0u;
          source.triangles.push_back(tri);
        }
        offset += count;
      }
    }
    shapes_.clear();
    return source;
  }

  // The texture `raw_name` of a material (decoded once per file and colour
  // space), or -1 with a warning when it cannot be used.
  enum class MapRole { Colour, Normal, Alpha };

  int texture_for(const std::string& raw_name, const std::string& material_name, const std::string& mtl_path,
                  MapRole role) {
    const ColorSpace space = role == MapRole::Colour ? ColorSpace::Srgb : ColorSpace::Linear;
    const std::string kind = role == MapRole::Colour ? "texture" : role == MapRole::Normal ? "normal map" : "alpha map";
    const std::string fallback = role == MapRole::Colour   ? "the material colour is used instead"
                                 : role == MapRole::Normal ? "the material is shaded without it"
                                                           : "the material is drawn whole";
    const std::vector<bundle_paths::TextureName> candidates = bundle_paths::texture_names(raw_name);
    if (candidates.empty()) return -1;
    const std::string& written = candidates.front().name;
    std::optional<std::string> path;
    for (const bundle_paths::TextureName& candidate : candidates) {
      const auto found = find_image(bundle_, mtl_path, candidate.name);
      if (!found) continue;
      path = found->path;
      if (candidate.file_name_only || found->match != ImageMatch::Path) {
        const FoundImage shown{found->path, found->match == ImageMatch::Path ? ImageMatch::FileName : found->match};
        warnings_.add(mtl_path + ": " + kind + " " + quoted(written) + " of material " + quoted(material_name) + " " +
                      describe_match(shown));
      }
      break;
    }
    if (!path) {
      warnings_.add(mtl_path + ": " + kind + " " + quoted(written) + " of material " + quoted(material_name) +
                    " is not in the bundle; " + fallback);
      return -1;
    }
    const auto key = std::make_pair(*path, space);
    if (const auto it = texture_slots_.find(key); it != texture_slots_.end()) return it->second;
    int slot = -1;
    try {
      Texture texture =
          decode_model_texture(*bundle_.find(*path), *path, limits_.max_texture_pixels, texture_pixels_left_);
      texture.color_space = space;
      if (role == MapRole::Normal && is_greyscale(texture)) {
        warnings_.add(*path + ": the bump map of material " + quoted(material_name) +
                      " is grey, a height map rather than a tangent-space normal map; the material is shaded "
                      "without it");
      } else {
        model_.textures.push_back(std::move(texture));
        slot = static_cast<int>(model_.textures.size()) - 1;
      }
    } catch (const ImportLimitError&) {
      throw;
    } catch (const std::exception& e) {
      warnings_.add(*path + ": " + kind + " of material " + quoted(material_name) + " cannot be used: " + e.what() +
                    "; " + fallback);
    }
    texture_slots_.emplace(key, slot);
    return slot;
  }

  // What the MTL says of the material's alpha: `d` (or `Tr`) below 1
  // blends the whole surface; `map_d` cuts it out where the map is dark
  // (its alpha where it has one, else its luminance), and so does a
  // `map_Kd` image with alpha, as Minetest's and most games' OBJ props are
  // drawn.
  void read_alpha(Material& material, const obj_text::MtlMaterial& said, const std::string& mtl_path) {
    if (said.opacity) {
      material.opacity = *said.opacity;
      material.alpha_mode = AlphaMode::Blend;
    }
    if (said.alpha_map) {
      const int map = texture_for(*said.alpha_map, said.name, mtl_path, MapRole::Alpha);
      if (map >= 0) {
        material.diffuse_texture = with_alpha_map(material.diffuse_texture, map);
        if (material.alpha_mode == AlphaMode::Opaque) material.alpha_mode = AlphaMode::Mask;
      }
      return;
    }
    if (material.alpha_mode == AlphaMode::Opaque && material.diffuse_texture >= 0) {
      material.alpha_mode = alpha_of_image(model_.textures[static_cast<std::size_t>(material.diffuse_texture)]);
    }
  }

  // A colour texture whose alpha is alpha map `map`'s (sampled nearest
  // where the sizes differ): a new texture, since the colour texture may
  // be another material's too; the map alone, white, without one.
  int with_alpha_map(int colour, int map) {
    const Texture alpha = model_.textures[static_cast<std::size_t>(map)];
    Texture combined;
    if (colour >= 0) {
      combined = model_.textures[static_cast<std::size_t>(colour)];
    } else {
      combined.path = alpha.path;
      combined.width = alpha.width;
      combined.height = alpha.height;
      combined.rgba.assign(alpha.rgba.size(), 255);
    }
    const bool has_alpha = alpha.min_alpha < 255;
    combined.min_alpha = 255;
    for (int y = 0; y < combined.height; ++y) {
      const int ay = static_cast<int>(static_cast<long long>(y) * alpha.height / combined.height);
      for (int x = 0; x < combined.width; ++x) {
        const int ax = static_cast<int>(static_cast<long long>(x) * alpha.width / combined.width);
        const std::uint8_t* a = &alpha.rgba[(static_cast<std::size_t>(ay) * alpha.width + ax) * 4];
        const auto value =
            has_alpha ? a[3] : static_cast<std::uint8_t>((a[0] * 54 + a[1] * 183 + a[2] * 19 + 128) >> 8);
        combined.rgba[(static_cast<std::size_t>(y) * combined.width + x) * 4 + 3] = value;
        combined.min_alpha = std::min(combined.min_alpha, value);
      }
    }
    combined.color_space = ColorSpace::Srgb;
    model_.textures.push_back(std::move(combined));
    return static_cast<int>(model_.textures.size()) - 1;
  }

  // The material as the MTL `mtl_path` describes it, its maps decoded.
  Material material_of(const obj_text::MtlMaterial& said, const std::string& mtl_path) {
    Material material;
    material.name = said.name;
    if (!said.colour_map.empty()) {
      material.diffuse_texture = texture_for(said.colour_map, said.name, mtl_path, MapRole::Colour);
    }
    material.diffuse = vec3_of(obj_text::base_colour(said, material.diffuse_texture >= 0 || has_vertex_colors_));
    if (!said.normal_map.empty()) {
      material.normal_texture = texture_for(said.normal_map, said.name, mtl_path, MapRole::Normal);
    }
    material.specular = vec3_of(said.specular);
    material.matte = said.matte;
    read_alpha(material, said, mtl_path);
    if (said.shininess) material.shininess = *said.shininess;
    return material;
  }

  void build_materials(std::vector<SourceTriangle>& triangles) {
    std::set<int> used;
    bool default_used = false;
    for (auto& tri : triangles) {
      if (tri.material < 0 || static_cast<std::size_t>(tri.material) >= tinyobj_materials_.size()) {
        tri.material = -1;
        default_used = true;
      } else {
        used.insert(tri.material);
      }
    }
    // Only materials that faces use: unused ones would cost texture decodes
    // and inflate the reported counts.
    std::map<int, int> slot;
    for (const int id : used) {
      slot[id] = static_cast<int>(model_.materials.size());
      model_.materials.push_back(material_of(reader_->material(id), reader_->source_of(id)));
    }
    if (default_used) {
      slot[-1] = static_cast<int>(model_.materials.size());
      Material fallback;
      fallback.name = "default";
      fallback.diffuse = vec3_of(obj_text::plain_colour(has_vertex_colors_));
      model_.materials.push_back(std::move(fallback));
    }
    for (auto& tri : triangles) tri.material = slot.at(tri.material);
  }

  const Bundle& bundle_;
  std::string obj_path_;
  ImportLimits limits_;
  ImportChoices choices_;
  ImportWarnings warnings_;
  std::unique_ptr<BundleMaterialReader> reader_;
  tinyobj::attrib_t attrib_;
  std::vector<tinyobj::shape_t> shapes_;
  std::vector<tinyobj::material_t> tinyobj_materials_;
  bool has_vertex_colors_ = false;
  // Per (bundle path, colour space): a file used both as a colour map and
  // as a normal map is decoded twice.
  std::map<std::pair<std::string, ColorSpace>, int> texture_slots_;
  std::uint64_t texture_pixels_left_ = kModelTexturePixels;
  Model model_;
};

}  // namespace

Model import_obj_bundle(const Bundle& bundle, const ImportLimits& limits, const ImportChoices& choices) {
  return Importer(bundle, limits, choices).run();
}

}  // namespace toond::scene
