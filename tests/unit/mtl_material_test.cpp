// What the shared MTL reader (common/obj_text) makes of each statement: the
// daemon's OBJ importer and toon's .glb writer both take a material's
// colour, maps, highlight and opacity from it, so these are what both draw.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "bundle_paths/statement_names.h"
#include "obj_text/mtl_material.h"

namespace toond::obj_text {
namespace {

constexpr const char* kMtl =
    "newmtl plain\nNs 10\n"
    "newmtl bright\nKd 2 0.5 -1\n"
    "newmtl flat\nKd 1 1 1\nKs 0 0 0\n"
    "newmtl chalk\nillum 1\nKs 0.5 0.5 0.5\n"
    "newmtl shiny\nillum 2\nKs 0.5 0.5 0.5\n"
    "newmtl glass\nd 0.25\n"
    "newmtl veil\nTr 0.75\n"
    "newmtl solid\nd 1\n"
    "newmtl painted\nmap_Kd -s 1 1 1 tex/a b.png\nmap_Bump -bm 2 n.png\nmap_d cut.png\n"
    "newmtl normed\nbump height.png\nnorm n2.png\n"
    "newmtl two words\nKd 0 0 1\n";

// Materials already read from an earlier library: read_mtl adds after them.
struct Read {
  std::vector<tinyobj::material_t> materials{1};
  std::map<std::string, int> by_name{{"earlier", 0}};
  std::vector<MtlMaterial> said;
  std::map<std::string, MtlMaterial> by_material;
};

Read read_all() {
  Read read;
  std::string warn, err;
  read.said = read_mtl(kMtl, &read.materials, &read.by_name, &warn, &err);
  for (const MtlMaterial& m : read.said) read.by_material[m.name] = m;
  return read;
}

std::string first_name(const std::string& statement) { return bundle_paths::texture_names(statement).front().name; }

TEST(MtlMaterial, EachMaterialInTinyobjsOrderUnderItsNameAndAlias) {
  const Read read = read_all();
  ASSERT_EQ(read.said.size(), 11u);
  ASSERT_EQ(read.materials.size(), 12u);
  for (std::size_t i = 0; i < read.said.size(); ++i) EXPECT_EQ(read.said[i].name, read.materials[i + 1].name);
  EXPECT_EQ(read.by_name.at("plain"), 1);
  EXPECT_EQ(read.by_name.at("two words"), 11);
  // prepare_obj_text's spelling of `usemtl two words`.
  EXPECT_EQ(read.by_name.at("two\x1fwords"), 11);
}

TEST(MtlMaterial, KdClampedAndWithoutItThePlainGreyOrWhite) {
  const Read read = read_all();
  const MtlMaterial& plain = read.by_material.at("plain");
  EXPECT_FALSE(plain.kd_given);
  EXPECT_EQ(base_colour(plain, false), (Rgb{0.8f, 0.8f, 0.8f}));
  EXPECT_EQ(base_colour(plain, true), (Rgb{1.0f, 1.0f, 1.0f}));
  EXPECT_EQ(plain_colour(false), (Rgb{kPlainGrey, kPlainGrey, kPlainGrey}));
  EXPECT_EQ(plain.shininess.value_or(-1.0f), 10.0f);
  const MtlMaterial& bright = read.by_material.at("bright");
  EXPECT_TRUE(bright.kd_given);
  EXPECT_EQ(base_colour(bright, false), (Rgb{1.0f, 0.5f, 0.0f}));
  EXPECT_EQ(base_colour(bright, true), (Rgb{1.0f, 0.5f, 0.0f}));
  EXPECT_FALSE(bright.shininess.has_value());
}

TEST(MtlMaterial, NoHighlightWhereKsIsBlackOrIllumSaysColourOnly) {
  const Read read = read_all();
  EXPECT_TRUE(read.by_material.at("flat").matte);
  EXPECT_TRUE(read.by_material.at("chalk").matte);
  EXPECT_FALSE(read.by_material.at("shiny").matte);
  EXPECT_FALSE(read.by_material.at("plain").matte);
  EXPECT_EQ(read.by_material.at("shiny").specular, (Rgb{0.5f, 0.5f, 0.5f}));
}

TEST(MtlMaterial, OpacityFromDOrTrBelowOne) {
  const Read read = read_all();
  EXPECT_EQ(read.by_material.at("glass").opacity.value_or(-1.0f), 0.25f);
  EXPECT_EQ(read.by_material.at("veil").opacity.value_or(-1.0f), 0.25f);  // Tr is 1 - d
  EXPECT_FALSE(read.by_material.at("solid").opacity.has_value());
  EXPECT_FALSE(read.by_material.at("plain").opacity.has_value());
}

TEST(MtlMaterial, MapsAsWrittenForTheSharedNameReading) {
  const Read read = read_all();
  const MtlMaterial& painted = read.by_material.at("painted");
  EXPECT_EQ(first_name(painted.colour_map), "tex/a b.png");
  EXPECT_EQ(first_name(painted.normal_map), "n.png");
  ASSERT_TRUE(painted.alpha_map.has_value());
  EXPECT_EQ(first_name(*painted.alpha_map), "cut.png");
  EXPECT_FALSE(painted.kd_given);
  EXPECT_EQ(first_name(read.by_material.at("normed").normal_map), "n2.png");  // norm over bump
  EXPECT_TRUE(read.by_material.at("plain").colour_map.empty());
  EXPECT_TRUE(read.by_material.at("plain").normal_map.empty());
}

}  // namespace
}  // namespace toond::obj_text
