#include "obj_text/mtl_material.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "obj_text/mtl_statements.h"
#include "obj_text/obj_text.h"

namespace toond::obj_text {
namespace {

Rgb clamped_colour(const tinyobj::real_t* rgb, float not_a_number) {
  Rgb c;
  for (std::size_t i = 0; i < 3; ++i) {
    const double value = rgb[i];
    c[i] = std::isfinite(value) ? static_cast<float>(std::clamp(value, 0.0, 1.0)) : not_a_number;
  }
  return c;
}

// tinyobj fills in its own defaults (Kd 0 without a texture and 0.6 with
// one, Ns 1), so a value counts only where `given` says the MTL wrote it.
MtlMaterial material_of(const tinyobj::material_t& source, const MtlStatements& given) {
  MtlMaterial material;
  material.name = source.name;
  material.kd_given = given.kd;
  material.kd = clamped_colour(source.diffuse, kPlainGrey);
  material.colour_map = given.map_kd.value_or(source.diffuse_texname);
  // `norm` names a normal map outright; tinyobj files map_Bump, map_bump
  // and bump under bump_texname, which Blender and most exporters use for
  // tangent-space normal maps.
  material.normal_map = given.norm.value_or(
      given.bump.value_or(!source.normal_texname.empty() ? source.normal_texname : source.bump_texname));
  material.alpha_map = given.map_d;
  // nvdiffrec MTLs (spot, bob) misuse Ks as (unused, roughness,
  // metalness), e.g. "Ks 0 0.25 0"; kept as written.
  material.specular = clamped_colour(source.specular, 0.0f);
  material.matte =
      (given.ks && material.specular == Rgb{}) || (given.illum && (source.illum == 0 || source.illum == 1));
  if (given.dissolve && std::isfinite(source.dissolve) && source.dissolve < 1.0) {
    material.opacity = static_cast<float>(std::clamp(static_cast<double>(source.dissolve), 0.0, 1.0));
  }
  if (given.ns && std::isfinite(source.shininess)) {
    material.shininess = static_cast<float>(std::clamp(static_cast<double>(source.shininess), 0.0, 1000.0));
  }
  return material;
}

}  // namespace

Rgb plain_colour(bool painted) {
  const float level = painted ? 1.0f : kPlainGrey;
  return {level, level, level};
}

Rgb base_colour(const MtlMaterial& material, bool painted) {
  return material.kd_given ? material.kd : plain_colour(painted);
}

std::vector<MtlMaterial> read_mtl(const std::string& text, std::vector<tinyobj::material_t>* materials,
                                  std::map<std::string, int>* by_name, std::string* warn, std::string* err) {
  const std::size_t first = materials->size();
  std::istringstream in(text);
  tinyobj::LoadMtl(by_name, materials, &in, warn, err);
  const std::map<std::string, MtlStatements> given = mtl_statements(text);
  std::vector<MtlMaterial> read;
  for (std::size_t i = first; i < materials->size(); ++i) {
    const tinyobj::material_t& source = (*materials)[i];
    const auto it = given.find(source.name);
    read.push_back(material_of(source, it == given.end() ? MtlStatements{} : it->second));
    // prepare_obj_text turns usemtl names with blanks into this alias.
    by_name->emplace(material_alias(source.name), static_cast<int>(i));
  }
  return read;
}

}  // namespace toond::obj_text
