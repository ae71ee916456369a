// Materials as games draw them, short of drawing (tests/integration/
// game_files_test.cpp draws them): images found by name as games find
// them, skins put on by the upload, the one-image rule, the alpha and
// highlight a format's engine gives where its files say nothing, and a
// frame's materials with the request's word on them.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "glb/glb_container.h"
#include "model_checks.h"
#include "pose_checks.h"
#include "render/plan/drawn_materials.h"
#include "render/plan/pass_plan.h"
#include "scene/import/iqm_import.h"
#include "scene/import/skins.h"
#include "scene/reading/image_lookup.h"

namespace toond::scene {
namespace {

using test_checks::make_bundle;
using test_checks::tiny_png;
namespace fs = std::filesystem;

const fs::path kGameFiles = TOOND_EXPORTED_DIR;

bool game_warns(const Model& model, const std::string& words) {
  for (const std::string& w : model.warnings) {
    if (w.find(words) != std::string::npos) return true;
  }
  return false;
}

std::string game_warnings(const Model& model) {
  std::string all;
  for (const std::string& w : model.warnings) all += w + "\n";
  return all;
}

// A PNG whose left half is wholly transparent (a cut-out), or whose every
// texel is half transparent (glass).
std::string alpha_png(std::uint8_t alpha_left, std::uint8_t alpha_right) {
  image::Image img;
  img.width = 4;
  img.height = 2;
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 4; ++x) img.rgba.insert(img.rgba.end(), {200, 100, 50, x < 2 ? alpha_left : alpha_right});
  }
  return image::encode_png(img);
}

// Game files read through the assimp helper (which ctest's binary lives
// apart from).
class GameFormats : public ::testing::Test {
 protected:
  void SetUp() override { setenv("TOOND_ASSIMP_CONVERTER", TOOND_ASSIMP_CONVERTER_PATH, 1); }
};

const std::string kTexturedQuad =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n";

TEST(ImageLookup, FindsImagesAsGamesNameThem) {
  const Bundle bundle = make_bundle({{"models/armor/armor_red.md3", "x"},
                                     {"models/armor/redarmor.tga", "t"},
                                     {"snout/snout.iqm", "x"},
                                     {"snout/lower.jpg", "j"},
                                     {"snout/lower_mask.jpg", "j"},
                                     {"skins/skin.png", "p"},
                                     {"a/twin.png", "p"},
                                     {"b/twin.png", "p"}});
  // Quake: a pack path from the game's root, no extension, another case.
  auto found = find_image(bundle, "models/armor/armor_red.md3", "models/armor/redArmor");
  ASSERT_TRUE(found);
  EXPECT_EQ(found->path, "models/armor/redarmor.tga");
  EXPECT_EQ(found->match, ImageMatch::AnyFormat);
  // An author's absolute path to a PNG, a JPEG shipped beside the model.
  found = find_image(bundle, "snout/snout.iqm", "/home/someone/Desktop/Snout/lower.png");
  ASSERT_TRUE(found);
  EXPECT_EQ(found->path, "snout/lower.jpg");
  // A file name found in another folder, when only one file has it.
  found = find_image(bundle, "snout/snout.iqm", "C:\\textures\\skin.png");
  ASSERT_TRUE(found);
  EXPECT_EQ(found->path, "skins/skin.png");
  EXPECT_EQ(found->match, ImageMatch::FileName);
  // The path as written, any case, from the naming file or the root.
  EXPECT_EQ(find_image(bundle, "snout/snout.iqm", "LOWER.JPG")->match, ImageMatch::Path);
  EXPECT_EQ(find_image(bundle, "snout/snout.iqm", "skins/skin.png")->path, "skins/skin.png");
  // Two files of the name elsewhere: no guess.
  EXPECT_FALSE(find_image(bundle, "snout/snout.iqm", "twin.png"));
  EXPECT_FALSE(find_image(bundle, "snout/snout.iqm", "missing.png"));
}

TEST(Skins, AnObjWithoutAnMtlTakesTheUploadsOneImage) {
  const Model model = import_bundle(make_bundle({{"prop.obj", kTexturedQuad}, {"prop.png", tiny_png(10, 200, 10)}}));
  ASSERT_EQ(model.materials.size(), 1u);
  EXPECT_EQ(model.materials[0].diffuse_texture, 0);
  EXPECT_TRUE(game_warns(model, "the upload's one image")) << game_warnings(model);
  // With an MTL, its materials say what they are drawn with: the image is
  // left over, and named.
  const Model with_mtl = import_bundle(make_bundle({{"prop.obj", "mtllib p.mtl\nusemtl red\n" + kTexturedQuad},
                                                    {"p.mtl", "newmtl red\nKd 1 0 0\n"},
                                                    {"prop.png", tiny_png(10, 200, 10)}}));
  EXPECT_EQ(with_mtl.materials[0].diffuse_texture, -1);
  EXPECT_TRUE(game_warns(with_mtl, "no material uses the image 'prop.png'")) << game_warnings(with_mtl);
  // Two images: which one is the skin is the upload's to say.
  const Model two = import_bundle(
      make_bundle({{"prop.obj", kTexturedQuad}, {"a.png", tiny_png(10, 200, 10)}, {"b.png", tiny_png(200, 10, 10)}}));
  EXPECT_EQ(two.materials[0].diffuse_texture, -1);
  EXPECT_TRUE(game_warns(two, "no material uses the images 'a.png', 'b.png'")) << game_warnings(two);
}

TEST(Skins, TheUploadsListPutsImagesOnMaterialsInOrderOrByName) {
  const std::string obj = "mtllib m.mtl\nusemtl body\n" + kTexturedQuad + "usemtl hat\nf 1/1 3/3 4/4\n";
  const std::string mtl = "newmtl body\nKd 0.5 0.5 0.5\nnewmtl hat\nKd 0.5 0.5 0.5\n";
  const test_checks::Files files = {
      {"m.obj", obj}, {"m.mtl", mtl}, {"skin.png", tiny_png(1, 2, 3)}, {"hat.png", tiny_png(4, 5, 6)}};
  ImportChoices choices;
  choices.textures = {"skin.png", "hat.png"};
  const Model ordered = import_bundle(make_bundle(files), {}, choices);
  ASSERT_EQ(ordered.materials.size(), 2u);
  EXPECT_EQ(ordered.textures[static_cast<std::size_t>(ordered.materials[0].diffuse_texture)].path, "skin.png");
  EXPECT_EQ(ordered.textures[static_cast<std::size_t>(ordered.materials[1].diffuse_texture)].path, "hat.png");
  EXPECT_EQ(ordered.materials[0].diffuse, glm::vec3(1.0f)) << "a skin shows as it is";
  choices.textures = {"hat:hat.png"};
  const Model named = import_bundle(make_bundle(files), {}, choices);
  EXPECT_EQ(named.materials[0].diffuse_texture, -1);
  EXPECT_EQ(named.textures[static_cast<std::size_t>(named.materials[1].diffuse_texture)].path, "hat.png");
  EXPECT_TRUE(game_warns(named, "no material uses the image 'skin.png'")) << game_warnings(named);

  for (const std::vector<std::string>& bad : std::vector<std::vector<std::string>>{
           {"a.png", "b.png", "c.png"}, {"nothere.png"}, {"cape:skin.png"}, {"body:skin.png", "hat.png"}}) {
    choices.textures = bad;
    try {
      import_bundle(make_bundle(files), {}, choices);
      ADD_FAILURE() << "accepted " << bad.front();
    } catch (const ImportError& e) {
      EXPECT_EQ(e.file(), "?textures") << e.what();
    }
  }
}

TEST(Skins, AnObjsAlphaIsReadFromItsMtlAndItsImage) {
  const auto material = [](const std::string& mtl, const std::string& png) {
    const Model m = import_bundle(
        make_bundle({{"m.obj", "mtllib m.mtl\nusemtl a\n" + kTexturedQuad}, {"m.mtl", mtl}, {"a.png", png}}));
    return m.materials.at(0);
  };
  const std::string opaque = tiny_png(9, 9, 9);
  EXPECT_EQ(material("newmtl a\nmap_Kd a.png\n", opaque).alpha_mode, AlphaMode::Opaque);
  EXPECT_EQ(material("newmtl a\nmap_Kd a.png\n", alpha_png(0, 255)).alpha_mode, AlphaMode::Mask);
  EXPECT_EQ(material("newmtl a\nmap_Kd a.png\n", alpha_png(128, 128)).alpha_mode, AlphaMode::Blend);
  const Material dissolved = material("newmtl a\nd 0.4\n", opaque);
  EXPECT_EQ(dissolved.alpha_mode, AlphaMode::Blend);
  EXPECT_FLOAT_EQ(dissolved.opacity, 0.4f);
  EXPECT_EQ(material("newmtl a\nTr 0.25\n", opaque).alpha_mode, AlphaMode::Blend);
  // map_d: the alpha map's luminance cuts the colour image.
  const Model cut = import_bundle(make_bundle({{"m.obj", "mtllib m.mtl\nusemtl a\n" + kTexturedQuad},
                                               {"m.mtl", "newmtl a\nmap_Kd a.png\nmap_d mask.png\n"},
                                               {"a.png", opaque},
                                               {"mask.png", tiny_png(0, 0, 0)}}));
  EXPECT_EQ(cut.materials[0].alpha_mode, AlphaMode::Mask);
  EXPECT_EQ(cut.textures[static_cast<std::size_t>(cut.materials[0].diffuse_texture)].min_alpha, 0);
  // Highlights: Ks 0 0 0 or illum 0/1 say there is none; saying nothing keeps it.
  EXPECT_TRUE(material("newmtl a\nKs 0 0 0\n", opaque).matte);
  EXPECT_TRUE(material("newmtl a\nKs 1 1 1\nillum 1\n", opaque).matte);
  EXPECT_FALSE(material("newmtl a\nKs 0.5 0.5 0.5\nillum 2\n", opaque).matte);
  EXPECT_FALSE(material("newmtl a\nKd 1 1 1\n", opaque).matte);
}

Model openarena_armor() {
  return import_bundle(
      make_bundle({{"models/powerups/armor/armor_red.md3", test::read_file(kGameFiles / "openarena/armor_red.md3")},
                   {"models/powerups/armor/redarmor.tga", test::read_file(kGameFiles / "openarena/redarmor.tga")}}));
}

// Quake draws its MD3 skins opaque whatever their alpha; Irrlicht alpha
// tests B3D skins at half; neither has highlights.
TEST_F(GameFormats, GetTheirEnginesAlphaAndNoHighlight) {
  const Model armor = openarena_armor();
  ASSERT_EQ(armor.textures.size(), 1u) << game_warnings(armor);
  EXPECT_LT(armor.textures[0].min_alpha, 255) << "the TGA has alpha";
  EXPECT_EQ(armor.materials[0].alpha_mode, AlphaMode::Opaque);
  EXPECT_TRUE(armor.materials[0].matte);
  const Model player =
      import_bundle(make_bundle({{"character.b3d", test::read_file(kGameFiles / "minetest/character.b3d")},
                                 {"character.png", test::read_file(kGameFiles / "minetest/character.png")}}));
  EXPECT_EQ(player.materials[0].alpha_mode, AlphaMode::Mask);
  EXPECT_FLOAT_EQ(player.materials[0].alpha_cutoff, 0.5f);
  EXPECT_TRUE(player.materials[0].matte);
  EXPECT_EQ(player.materials[0].diffuse, glm::vec3(1.0f));
}

// A Quake 3 `.skin` file names each surface's image; the MD3's materials
// are named after its surfaces.
TEST_F(GameFormats, AnMd3TakesItsSkinFilesImages) {
  const Model armor =
      import_bundle(make_bundle({{"armor_red.md3", test::read_file(kGameFiles / "openarena/armor_red.md3")},
                                 {"armor_red_default.skin", "tag_floor,\nunnamed_obj_0,skins/crimson.tga\n"},
                                 {"skins/crimson.tga", test::read_file(kGameFiles / "openarena/redarmor.tga")}}));
  ASSERT_EQ(armor.materials.size(), 1u);
  EXPECT_EQ(armor.materials[0].name, "unnamed_obj_0");
  ASSERT_GE(armor.materials[0].diffuse_texture, 0) << game_warnings(armor);
  EXPECT_EQ(armor.textures[static_cast<std::size_t>(armor.materials[0].diffuse_texture)].path, "skins/crimson.tga");
}

TEST(Iqm, FrankieIsReadWithItsSkeletonMeshesAndTheClipBesideIt) {
  const fs::path dir = kGameFiles / "cube2/frankie";
  const std::string model = test::read_file(dir / "Frankie.iqm");
  const std::string run = test::read_file(dir / "Frankie_Run.iqm");
  const auto contents = iqm_contents(model);
  ASSERT_TRUE(contents);
  EXPECT_EQ(contents->meshes, 2u);
  EXPECT_EQ(contents->joints, 52u);
  const auto clips = iqm_contents(run);
  ASSERT_TRUE(clips);
  EXPECT_EQ(clips->meshes, 0u);
  EXPECT_EQ(clips->poses, 52u);
  EXPECT_EQ(clips->clip_names, std::vector<std::string>{"Frankie_Run"});
  EXPECT_FALSE(iqm_contents("INTERQUAKEMODEL"));

  const Model frankie = import_bundle(make_bundle({{"Frankie.iqm", model}, {"Frankie_Run.iqm", run}}));
  ASSERT_EQ(frankie.materials.size(), 2u);
  EXPECT_EQ(frankie.materials[0].name, "Tail");
  EXPECT_EQ(frankie.materials[1].name, "Body");
  ASSERT_TRUE(frankie.rig);
  EXPECT_EQ(frankie.rig->joint_count, 52u);
  ASSERT_EQ(frankie.rig->clips.size(), 1u);
  EXPECT_EQ(frankie.rig->clips[0].name, "Frankie_Run");
  EXPECT_NEAR(frankie.rig->clips[0].duration, 18.0 / 24.0, 1e-6);
  EXPECT_EQ(frankie.rig->clips[0].frame_rate, 24.0);
  // Z up by the format's convention: the squirrel stands on +Y.
  const Bounds& b = frankie.mesh.bounds;
  EXPECT_GT(b.max.y - b.min.y, 0.5f * (b.max.z - b.min.z));
}

TEST(Iqm, AFileOfClipsAloneOrOfAnotherSkeletonIsSaidSo) {
  const fs::path dir = kGameFiles / "cube2";
  const std::string run = test::read_file(dir / "frankie/Frankie_Run.iqm");
  try {
    import_bundle(make_bundle({{"Frankie_Run.iqm", run}}));
    ADD_FAILURE() << "a clip alone was taken for a model";
  } catch (const ImportError& e) {
    EXPECT_EQ(e.file(), "Frankie_Run.iqm");
    EXPECT_NE(std::string(e.what()).find("holds only 1 clip ('Frankie_Run') for a skeleton of 52 joints"),
              std::string::npos)
        << e.what();
  }
  // Snout's skeleton has 75 joints: Frankie's run does not fit it.
  const Model snout = import_bundle(
      make_bundle({{"snoutx10k.iqm", test::read_file(dir / "snoutx10k/snoutx10k.iqm")}, {"Frankie_Run.iqm", run}}));
  EXPECT_TRUE(!snout.rig || snout.rig->clips.empty());
  EXPECT_TRUE(
      game_warns(snout, "Frankie_Run.iqm: its clips are left out: its clips move 52 joints and the model has 75"))
      << game_warnings(snout);
  // Cut short, it is refused naming the file.
  EXPECT_THROW(
      import_bundle(make_bundle({{"Frankie.iqm", test::read_file(dir / "frankie/Frankie.iqm").substr(0, 2000)}})),
      ImportError);
}

TEST_F(GameFormats, AnMd5AnimsClipGoesOntoItsMeshByJointName) {
  const fs::path dir = kGameFiles / "cube2/ffflag";
  const Model flag = import_bundle(make_bundle({{"ffflag.md5mesh", test::read_file(dir / "ffflag.md5mesh")},
                                                {"ffflag.md5anim", test::read_file(dir / "ffflag.md5anim")}}));
  ASSERT_TRUE(flag.rig);
  ASSERT_EQ(flag.rig->clips.size(), 1u) << game_warnings(flag);
  EXPECT_GT(flag.rig->clips[0].duration, 1.0);
  EXPECT_TRUE(flag.rig->clips[0].frame_rate);
  try {
    import_bundle(make_bundle({{"ffflag.md5anim", test::read_file(dir / "ffflag.md5anim")}}));
    ADD_FAILURE() << "a clip alone was taken for a model";
  } catch (const ImportError& e) {
    EXPECT_NE(std::string(e.what()).find("upload it together with the model it animates"), std::string::npos)
        << e.what();
  }
}

// Mixamo-style FBX files: the walker with its mesh (make_walker.py), and its
// armature's two actions alone (make_walker_clips.py: Blender's FBX of the
// armature, no mesh). Uploaded together, the second file's clips go onto
// the walker by joint name and pose it as its own clips do; alone, it is
// said to hold clips and no mesh.
TEST_F(GameFormats, AnAnimationOnlyFbxAddsItsClipsToTheCharacterBesideIt) {
  const fs::path blender = fs::path(TOOND_EXPORTED_DIR) / "blender";
  const std::string walker = test::read_file(blender / "walker.fbx");
  const std::string clips = test::read_file(blender / "walker_clips.fbx");
  const Model both = import_bundle(make_bundle({{"walker.fbx", walker}, {"walker_clips.fbx", clips}}));
  ASSERT_TRUE(both.rig);
  ASSERT_EQ(both.rig->clips.size(), 4u) << game_warnings(both);
  EXPECT_EQ(both.rig->clips[0].name, "Walk");
  const auto walk = both.rig->find_clip("Armature|Armature|Walk");
  ASSERT_TRUE(walk);
  EXPECT_EQ(both.rig->clips[*walk].frame_rate, 24.0);
  for (const double time : {0.0, 0.25, 0.5}) {
    EXPECT_LT(test_checks::farthest_from(test_checks::posed_points(both, *walk, time),
                                         test_checks::posed_points(both, 0, time)),
              1e-3)
        << "at " << time << " s";
  }
  try {
    import_bundle(make_bundle({{"walker_clips.fbx", clips}}));
    ADD_FAILURE() << "a clip file alone was taken for a model";
  } catch (const ImportError& e) {
    EXPECT_NE(std::string(e.what()).find("walker_clips.fbx holds only 2 clips"), std::string::npos) << e.what();
  }
}

// The player's twin split in two as Mixamo-style exports come: the
// character without its clip, and a file of the clip alone (no mesh, no
// skin). Uploaded together, the clip goes back onto the character by
// joint name and poses it as the whole file does.
TEST(ClipFiles, AnAnimationOnlyGltfAddsItsClipToTheModelByJointName) {
  const std::string whole = test::read_file(kGameFiles / "minetest/character_twin.glb");
  const auto chunks = glb::glb_chunks(whole);
  ASSERT_TRUE(chunks);
  nlohmann::json model = nlohmann::json::parse(chunks->json);
  nlohmann::json clips = model;
  model.erase("animations");
  clips.erase("meshes");
  clips.erase("skins");
  for (nlohmann::json& node : clips["nodes"]) {
    node.erase("mesh");
    node.erase("skin");
  }
  const std::string png = test::read_file(kGameFiles / "minetest/character.png");
  const Model original = import_bundle(make_bundle({{"character.glb", whole}, {"character.png", png}}));
  const Model joined = import_bundle(make_bundle({{"character.glb", glb::glb_container(model.dump(), chunks->bin)},
                                                  {"walk.glb", glb::glb_container(clips.dump(), chunks->bin)},
                                                  {"character.png", png}}));
  ASSERT_TRUE(original.rig && joined.rig);
  ASSERT_EQ(joined.rig->clips.size(), 1u) << game_warnings(joined);
  for (const double time : {0.5, 2.95, 3.0}) {
    EXPECT_LT(test_checks::farthest_from(test_checks::posed_points(joined, 0, time),
                                         test_checks::posed_points(original, 0, time)),
              1e-5)
        << "at " << time << " s";
  }
  // A clip whose joints the model lacks is left out, naming them.
  for (nlohmann::json& node : clips["nodes"]) {
    if (node.contains("name")) node["name"] = "other " + node["name"].get<std::string>();
  }
  const Model refused = import_bundle(make_bundle({{"character.glb", glb::glb_container(model.dump(), chunks->bin)},
                                                   {"walk.glb", glb::glb_container(clips.dump(), chunks->bin)},
                                                   {"character.png", png}}));
  EXPECT_TRUE(!refused.rig || refused.rig->clips.empty());
  EXPECT_TRUE(game_warns(refused, "walk.glb: clip")) << game_warnings(refused);
  EXPECT_TRUE(game_warns(refused, "is left out: the model has no joint named 'other ")) << game_warnings(refused);
  // Alone, it is said to hold a clip and no mesh.
  try {
    import_bundle(make_bundle({{"walk.glb", glb::glb_container(clips.dump(), chunks->bin)}}));
    ADD_FAILURE() << "a clip alone was taken for a model";
  } catch (const ImportError& e) {
    EXPECT_NE(std::string(e.what()).find("walk.glb holds only 1 clip"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace toond::scene

namespace toond::render {
namespace {

scene::Model model_with(scene::Material material, int texture_side, std::uint8_t min_alpha) {
  scene::Model model;
  scene::Texture texture;
  texture.width = texture.height = texture_side;
  texture.min_alpha = min_alpha;
  model.textures.push_back(texture);
  material.diffuse_texture = 0;
  model.materials.push_back(material);
  return model;
}

TEST(DrawnMaterials, AMaskThatCutsNothingIsDrawnOpaque) {
  scene::Material mask;
  mask.alpha_mode = scene::AlphaMode::Mask;
  RenderParams params;
  EXPECT_TRUE(drawn_materials(model_with(mask, 16, 0), params)[0].cuts);
  EXPECT_FALSE(drawn_materials(model_with(mask, 16, 255), params)[0].cuts);
  EXPECT_FLOAT_EQ(drawn_materials(model_with(mask, 16, 255), params)[0].tested_cutoff(), -1.0f);
  scene::Material blend;
  blend.alpha_mode = scene::AlphaMode::Blend;
  EXPECT_TRUE(drawn_materials(model_with(blend, 16, 100), params)[0].blended);
  EXPECT_FALSE(drawn_materials(model_with(blend, 16, 255), params)[0].blended);
  // The request's word: opaque.
  params.materials["default"].alpha = scene::AlphaMode::Opaque;
  mask.name = "default";
  EXPECT_FALSE(drawn_materials(model_with(mask, 16, 0), params)[0].cuts);
}

TEST(DrawnMaterials, SmallTexturesMagnifyNearestUnlessTheFileOrRequestSays) {
  scene::Material m;
  RenderParams params;
  EXPECT_TRUE(drawn_materials(model_with(m, 64, 255), params)[0].nearest_magnification);
  EXPECT_TRUE(drawn_materials(model_with(m, kPixelArtTexels, 255), params)[0].nearest_magnification);
  EXPECT_FALSE(drawn_materials(model_with(m, kPixelArtTexels + 1, 255), params)[0].nearest_magnification);
  m.sampler.magnification = scene::TextureFilter::Linear;
  EXPECT_FALSE(drawn_materials(model_with(m, 64, 255), params)[0].nearest_magnification);
  params.texture_filter = TextureFilterChoice::Nearest;
  EXPECT_TRUE(drawn_materials(model_with(m, 1024, 255), params)[0].nearest_magnification);
}

TEST(DrawnMaterials, AMatteMaterialHasNoHighlightUnlessEveryOneIsAskedFor) {
  scene::Material matte;
  matte.matte = true;
  RenderParams params;
  EXPECT_FALSE(drawn_materials(model_with(matte, 16, 255), params)[0].specular);
  params.specular.source = SpecularSource::All;
  EXPECT_TRUE(drawn_materials(model_with(matte, 16, 255), params)[0].specular);
  // No material with a highlight: the plan leaves the highlight out.
  ModelTraits traits;
  traits.has_specular_materials = false;
  RenderParams lit;
  lit.lights = {Light{}};
  EXPECT_FALSE(plan_passes(lit, traits).shading.has(ToonFeature::Specular));
  traits.has_specular_materials = true;
  EXPECT_TRUE(plan_passes(lit, traits).shading.has(ToonFeature::Specular));
}

}  // namespace
}  // namespace toond::render
