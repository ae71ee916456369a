#pragma once
// What an MTL says of each of its materials, read one way for the daemon's
// OBJ importer and for the .glb `toon gallery` writes from an OBJ, so that
// the .glb draws as its OBJ does; and the grey of what nothing colours.
#include <tiny_obj_loader.h>

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace toond::obj_text {

using Rgb = std::array<float, 3>;

// The grey toond draws what nothing colours in: faces with no material, a
// material with neither Kd nor a texture.
inline constexpr float kPlainGrey = 0.8f;

struct MtlMaterial {
  std::string name;
  bool kd_given = false;
  Rgb kd{kPlainGrey, kPlainGrey, kPlainGrey};  // Kd in 0..1; a part that is not a number reads as grey
  std::string colour_map;                      // map_Kd as written (bundle_paths::texture_names reads it); "": none
  std::string normal_map;                      // norm, else map_Bump, map_bump or bump, as written; "": none
  std::optional<std::string> alpha_map;        // map_d as written
  Rgb specular{};                              // Ks in 0..1; a part that is not a number reads as 0
  // No highlight: the MTL says Ks 0 0 0, or illum 0 or 1 (colour only,
  // colour and ambient).
  bool matte = false;
  std::optional<float> opacity;    // d (or Tr) below 1, down to 0; none: opaque
  std::optional<float> shininess;  // Ns, in 0..1000
};

// The colour of faces with no material: white where vertex colours (or a
// texture) paint them, grey where nothing does.
Rgb plain_colour(bool painted);

// The colour a material multiplies its texture or vertex colours by: its Kd;
// without one (nvdiffrec-style MTLs give only map_Kd) plain_colour, where
// `painted` says whether a texture or vertex colours paint it.
Rgb base_colour(const MtlMaterial& material, bool painted);

// Reads one MTL file's text as tinyobj::LoadMtl does, adding its materials
// to tinyobj's lists (what a tinyobj::MaterialReader hands back) under their
// names and under the aliases prepare_obj_text gives usemtl names with
// blanks (material_alias). Returns what the MTL says of each material
// added, in the same order; LoadMtl's messages go to `warn` and `err`.
std::vector<MtlMaterial> read_mtl(const std::string& text, std::vector<tinyobj::material_t>* materials,
                                  std::map<std::string, int>* by_name, std::string* warn, std::string* err);

}  // namespace toond::obj_text
