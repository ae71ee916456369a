// Formats read through assimp in the toond-assimp-convert helper: Blender's
// FBX and COLLADA come in upright and in metres with their clips, textures
// named by another machine's path are found by file name, files without
// normals are shaded by angle, and a helper that fails in any way is an
// ImportError naming the file.
#include <gtest/gtest.h>

#include <stdlib.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <sstream>
#include <string>

#include "fake_helpers.h"
#include "model_checks.h"
#include "pose_checks.h"
#include "scene/import/assimp_import.h"
#include "scene/import/bundle_import.h"
#include "scene/mesh/mesh_processing.h"
#include "scene/reading/import_error.h"
#include "support/shared_models.h"
#include "support/stored_zip.h"

namespace toond::scene {
namespace {

using test::read_file;
using test_checks::expect_well_formed;
using test_checks::Files;
using test_checks::has_warning;
using test_checks::make_bundle;
using test_checks::warnings_of;

const std::filesystem::path kBlender = TOOND_EXPORTED_DIR "/blender";

// A 2 x 2 cube written by hand in the Object File Format: positions and
// quads, no normals.
constexpr const char* kOffCube =
    "OFF\n8 6 0\n-1 -1 -1\n1 -1 -1\n1 1 -1\n-1 1 -1\n-1 -1 1\n1 -1 1\n1 1 1\n-1 1 1\n"
    "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5\n4 0 4 7 3\n";

// A 1 m x 2 m quad in centimetres, Z up, whose texture is named by the
// artist's Windows path, as COLLADA exporters on Windows write it.
constexpr const char* kTexturedQuadDae = R"(<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="centimeter" meter="0.01"/><up_axis>Z_UP</up_axis></asset>
  <library_images>
    <image id="checker" name="checker"><init_from>C:\Users\artist\maps\Checker.png</init_from></image>
  </library_images>
  <library_effects>
    <effect id="paint-fx"><profile_COMMON>
      <newparam sid="surface"><surface type="2D"><init_from>checker</init_from></surface></newparam>
      <newparam sid="sampler"><sampler2D><source>surface</source></sampler2D></newparam>
      <technique sid="common"><lambert><diffuse><texture texture="sampler" texcoord="UVMap"/></diffuse></lambert></technique>
    </profile_COMMON></effect>
  </library_effects>
  <library_materials><material id="paint" name="paint"><instance_effect url="#paint-fx"/></material></library_materials>
  <library_geometries>
    <geometry id="quad" name="quad"><mesh>
      <source id="quad-pos"><float_array id="quad-pos-a" count="12">0 0 0 100 0 0 100 0 200 0 0 200</float_array>
        <technique_common><accessor source="#quad-pos-a" count="4" stride="3">
          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
        </accessor></technique_common></source>
      <source id="quad-uv"><float_array id="quad-uv-a" count="8">0 0 1 0 1 1 0 1</float_array>
        <technique_common><accessor source="#quad-uv-a" count="4" stride="2">
          <param name="S" type="float"/><param name="T" type="float"/>
        </accessor></technique_common></source>
      <vertices id="quad-v"><input semantic="POSITION" source="#quad-pos"/></vertices>
      <triangles material="paint" count="2">
        <input semantic="VERTEX" source="#quad-v" offset="0"/>
        <input semantic="TEXCOORD" source="#quad-uv" offset="0" set="0"/>
        <p>0 1 2 0 2 3</p>
      </triangles>
    </mesh></geometry>
  </library_geometries>
  <library_visual_scenes><visual_scene id="scene">
    <node id="quad-node" name="quad"><instance_geometry url="#quad">
      <bind_material><technique_common><instance_material symbol="paint" target="#paint">
        <bind_vertex_input semantic="UVMap" input_semantic="TEXCOORD" input_set="0"/>
      </instance_material></technique_common></bind_material>
    </instance_geometry></node>
  </visual_scene></library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
)";

// Every test runs the helper the build made (the daemon finds it beside
// itself; this test binary lives elsewhere).
class AssimpImport : public ::testing::Test {
 protected:
  void SetUp() override { setenv("TOOND_ASSIMP_CONVERTER", TOOND_ASSIMP_CONVERTER_PATH, 1); }
};
using AssimpImportErrors = AssimpImport;

std::string conversion_error(const Files& files, const ImportLimits& limits = {}) {
  try {
    import_bundle(make_bundle(files), limits);
  } catch (const ImportError& e) {
    EXPECT_EQ(e.file(), files.front().first);
    return e.what();
  }
  ADD_FAILURE() << files.front().first << " was read";
  return {};
}

TEST_F(AssimpImport, EveryExtensionIsKnownAndOwnReadersKeepTheirs) {
  for (const char* path : {"a.fbx", "b/C.DAE", "c.3ds", "d.3mf", "e.off", "f.x"}) {
    EXPECT_TRUE(read_through_assimp(path)) << path;
  }
  for (const char* path : {"a.obj", "b.stl", "c.ply", "d.glb", "e.gltf", "f.m", "g.png", "h.blend"}) {
    EXPECT_FALSE(read_through_assimp(path)) << path;
  }
}

TEST_F(AssimpImport, BlendersFbxCharacterComesWithItsClipsUprightAndInMetres) {
  const Model model = import_bundle(make_bundle({{"rigged.fbx", read_file(kBlender / "rigged.fbx")}}));
  expect_well_formed(model);
  ASSERT_TRUE(model.rig);
  EXPECT_EQ(model.rig->clip_names(), "\"Bend\", \"Twist\"");
  EXPECT_EQ(model.rig->joint_count, 3u);
  EXPECT_EQ(model.rig->morph_target_count, 1u);
  // The bar is 2 m tall along +Y, as in the glTF twin; the FBX stores
  // centimetres (UnitScaleFactor 1).
  const glm::vec3 size = model.mesh.bounds.max - model.mesh.bounds.min;
  EXPECT_NEAR(size.y, 2.0f, 1e-4f);
  EXPECT_NEAR(size.x, 0.4f, 1e-4f);
  EXPECT_NEAR(size.z, 0.4f, 1e-4f);
  EXPECT_TRUE(has_warning(model, "rigged.fbx: scaled to metres (the file's unit is 1 cm)")) << warnings_of(model);
  EXPECT_FALSE(has_warning(model, "FB_ngon_encoding")) << warnings_of(model);
}

// Blender's FBX of the bending bar (tests/exported/blender/make_rigged.py),
// posed at 0.5 s of Bend, against the OBJ Blender wrote of that moment from
// its own armature deform and shape key: the bones, the skin weights and
// the shape key's animated weight all arrive through the helper.
TEST_F(AssimpImport, BlendersFbxBendsWhereBlenderPutIt) {
  const Model model = import_bundle(make_bundle({{"rigged.fbx", read_file(kBlender / "rigged.fbx")}}));
  ASSERT_TRUE(model.rig);
  const Rig& rig = *model.rig;
  const std::vector<glm::dvec3> blender = test_checks::obj_positions(read_file(kBlender / "rigged_pose_bend_0_5.obj"));
  ASSERT_EQ(blender.size(), 72u);
  const auto posed_at = [&](double t) { return test_checks::posed_points(model, *rig.find_clip("Bend"), t); };
  const std::vector<glm::dvec3> ours = posed_at(0.5);
  EXPECT_LT(test_checks::farthest_from(ours, blender), 1e-5);
  EXPECT_LT(test_checks::farthest_from(blender, ours), 1e-5);
  // The shape key's weight is 0 at the start: the middle ring is 0.2 in.
  EXPECT_GT(test_checks::farthest_from(blender, posed_at(0.0)), 0.1);
}

// Blender's walking character (tests/exported/blender/make_walker.py: 13
// bones, three materials) as glTF, FBX and COLLADA, posed at 0.25 s of its
// walk, against the OBJ Blender wrote of that moment.
class WalkerTwin : public ::testing::TestWithParam<const char*> {
 protected:
  void SetUp() override { setenv("TOOND_ASSIMP_CONVERTER", TOOND_ASSIMP_CONVERTER_PATH, 1); }
};

TEST_P(WalkerTwin, WalksWhereBlenderPutIt) {
  const std::string name = GetParam();
  const Model model = import_bundle(make_bundle({{name, read_file(kBlender / name)}}));
  ASSERT_TRUE(model.rig);
  const Rig& rig = *model.rig;
  EXPECT_EQ(rig.joint_count, 13u);
  // COLLADA carries the active action alone, under the armature's name.
  const std::size_t walk = rig.clips.size() == 1 ? 0 : *rig.find_clip("Walk");
  EXPECT_NEAR(rig.clips[walk].duration, 1.0, 1e-6);
  const std::vector<glm::dvec3> ours = test_checks::posed_points(model, walk, 0.25);
  const std::vector<glm::dvec3> blender = test_checks::obj_positions(read_file(kBlender / "walker_walk_0_25.obj"));
  ASSERT_GT(blender.size(), 100u);
  EXPECT_LT(test_checks::farthest_from(ours, blender), 1e-5);
  EXPECT_LT(test_checks::farthest_from(blender, ours), 1e-5);
}

INSTANTIATE_TEST_SUITE_P(Blender, WalkerTwin, ::testing::Values("walker.glb", "walker.fbx", "walker.dae"),
                         [](const auto& param_info) {
                           std::string name = param_info.param;
                           return name.substr(name.find('.') + 1);
                         });

TEST_F(AssimpImport, AColladaFileIsUprightInMetresAndFindsItsTextureByFileName) {
  const Model model = import_bundle(
      make_bundle({{"art/quad.dae", kTexturedQuadDae}, {"art/checker.png", test_checks::tiny_png(200, 40, 40)}}));
  expect_well_formed(model);
  const glm::vec3 size = model.mesh.bounds.max - model.mesh.bounds.min;
  EXPECT_NEAR(size.x, 1.0f, 1e-5f);
  EXPECT_NEAR(size.y, 2.0f, 1e-5f);  // the file's +Z
  EXPECT_NEAR(size.z, 0.0f, 1e-5f);
  ASSERT_EQ(model.textures.size(), 1u);
  EXPECT_EQ(model.textures[0].path, "art/checker.png");
  EXPECT_TRUE(has_warning(model, "was found by its file name alone, as 'art/checker.png'")) << warnings_of(model);
}

TEST_F(AssimpImport, ATextureNotInTheUploadIsAWarning) {
  const Model model = import_bundle(make_bundle({{"quad.dae", kTexturedQuadDae}}));
  EXPECT_TRUE(model.textures.empty());
  EXPECT_TRUE(has_warning(model, "is not in the upload")) << warnings_of(model);
}

TEST_F(AssimpImport, AFileWithoutNormalsIsShadedByAngle) {
  // The glTF answer has no NORMAL; glTF's own rule (flat) would give the
  // same cube, so a smooth angle past 90° shows which rule was applied.
  const Model flat = import_bundle(make_bundle({{"cube.off", kOffCube}}));
  expect_well_formed(flat);
  EXPECT_EQ(flat.mesh.triangle_count(), 12u);
  EXPECT_EQ(flat.mesh.positions.size(), 24u);
  ImportChoices smooth;
  smooth.smooth_angle = 120.0;
  const Model rounded = import_bundle(make_bundle({{"cube.off", kOffCube}}), {}, smooth);
  EXPECT_EQ(rounded.mesh.positions.size(), 8u);
}

// A 3MF package as slicers write one: a 10 x 10 x 30 mm column standing on
// the build plate (3MF is Z-up by its specification), one red base
// material.
std::string column_3mf() {
  const std::string model = R"(<?xml version="1.0" encoding="UTF-8"?>
<model unit="millimeter" xml:lang="en-US" xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02">
 <resources>
  <basematerials id="1"><base name="Red" displaycolor="#CC2020FF"/></basematerials>
  <object id="2" type="model" pid="1" pindex="0"><mesh>
   <vertices>
    <vertex x="0" y="0" z="0"/><vertex x="10" y="0" z="0"/><vertex x="10" y="10" z="0"/><vertex x="0" y="10" z="0"/>
    <vertex x="0" y="0" z="30"/><vertex x="10" y="0" z="30"/><vertex x="10" y="10" z="30"/><vertex x="0" y="10" z="30"/>
   </vertices>
   <triangles>
    <triangle v1="0" v2="2" v3="1"/><triangle v1="0" v2="3" v3="2"/><triangle v1="4" v2="5" v3="6"/>
    <triangle v1="4" v2="6" v3="7"/><triangle v1="0" v2="1" v3="5"/><triangle v1="0" v2="5" v3="4"/>
    <triangle v1="1" v2="2" v3="6"/><triangle v1="1" v2="6" v3="5"/><triangle v1="2" v2="3" v3="7"/>
    <triangle v1="2" v2="7" v3="6"/><triangle v1="3" v2="0" v3="4"/><triangle v1="3" v2="4" v3="7"/>
   </triangles>
  </mesh></object>
 </resources>
 <build><item objectid="2"/></build>
</model>
)";
  return test::stored_zip(
      {{"[Content_Types].xml",
        R"(<?xml version="1.0" encoding="UTF-8"?><Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types">)"
        R"(<Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/>)"
        R"(<Default Extension="model" ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/></Types>)"},
       {"_rels/.rels",
        R"(<?xml version="1.0" encoding="UTF-8"?><Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">)"
        R"(<Relationship Target="/3D/3dmodel.model" Id="rel0" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/>)"
        R"(</Relationships>)"},
       {"3D/3dmodel.model", model}});
}

TEST_F(AssimpImport, A3mfColumnStandsUpright) {
  const Model model = import_bundle(make_bundle({{"column.3mf", column_3mf()}}));
  expect_well_formed(model);
  EXPECT_EQ(model.mesh.triangle_count(), 12u);
  const glm::vec3 size = model.mesh.bounds.max - model.mesh.bounds.min;
  EXPECT_NEAR(size.y, 30.0f, 1e-4f);  // the file's +Z
  EXPECT_NEAR(size.x, 10.0f, 1e-4f);
  EXPECT_NEAR(size.z, 10.0f, 1e-4f);
  // Z-up is 3MF's convention, the default; `up=y` takes the file as Y-up.
  ImportChoices y_up;
  y_up.up = ImportChoices::Up::Y;
  const Model lying = import_bundle(make_bundle({{"column.3mf", column_3mf()}}), {}, y_up);
  EXPECT_NEAR(lying.mesh.bounds.max.z - lying.mesh.bounds.min.z, 30.0f, 1e-4f);
  // #CC2020 is sRGB; materials hold linear colour.
  ASSERT_EQ(model.materials.size(), 1u);
  EXPECT_NEAR(model.materials[0].diffuse.r, 0.6038f, 1e-3f);
  EXPECT_NEAR(model.materials[0].diffuse.g, 0.0144f, 1e-3f);
}

TEST_F(AssimpImport, UpZTurnsAFileWithoutAxes) {
  ImportChoices z_up;
  z_up.up = ImportChoices::Up::Z;
  const Model model =
      import_bundle(make_bundle({{"cube.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 0 3\n3 0 1 2\n"}}), {}, z_up);
  const glm::vec3 size = model.mesh.bounds.max - model.mesh.bounds.min;
  EXPECT_NEAR(size.y, 3.0f, 1e-6f);
}

TEST_F(AssimpImportErrors, BrokenFilesAreRefusedWithTheirReason) {
  EXPECT_NE(conversion_error({{"empty.fbx", ""}}).find("empty.fbx: the file is empty"), std::string::npos);
  // The reader's own reasons, not a crash or a stop.
  const std::string garbage = conversion_error({{"noise.fbx", std::string(1000, '\x7f')}});
  EXPECT_NE(garbage.find("noise.fbx: FBX-Parser"), std::string::npos) << garbage;
  const std::string fbx = read_file(kBlender / "rigged.fbx");
  const std::string cut = conversion_error({{"cut.fbx", fbx.substr(0, fbx.size() / 2)}});
  EXPECT_NE(cut.find("cut.fbx: FBX-Tokenize"), std::string::npos) << cut;
  // Four billion vertices: the memory limit, or under AddressSanitizer
  // (no RLIMIT_AS) its bound on one allocation, which ends the helper.
  const std::string off = conversion_error({{"lie.off", "OFF\n4000000000 1 0\n0 0 0\n"}});
  EXPECT_TRUE(off.find("lie.off: reading it needs more than the memory limit") != std::string::npos ||
              off.find("lie.off: the OFF reader crashed (SIGABRT)") != std::string::npos)
      << off;
}

// Blender 3.4 writes a skinned mesh with a shape key as a <skin> and a
// <morph> of one geometry; Debian's assimp (5.2.5) cannot resolve that pair.
TEST_F(AssimpImportErrors, BlendersColladaSkinWithAShapeKeyIsRefusedWithAssimpsReason) {
  const std::string error = conversion_error({{"rigged.dae", read_file(kBlender / "rigged.dae")}});
  EXPECT_NE(error.find("rigged.dae: Unable to resolve library reference"), std::string::npos) << error;
}

TEST_F(AssimpImportErrors, AHelperThatCrashesHangsOrBabblesIsARefusalNotACrash) {
  const Files files = {{"cube.off", kOffCube}};
  test_checks::FakeHelpers fakes;

  setenv("TOOND_ASSIMP_CONVERTER", fakes.make("crash", "kill -SEGV $$").c_str(), 1);
  std::string error = conversion_error(files);
  EXPECT_NE(error.find("cube.off: the OFF reader crashed (SIGSEGV)"), std::string::npos) << error;

  setenv("TOOND_ASSIMP_CONVERTER", fakes.make("babble", "cat >/dev/null; printf 'not glTF at all'").c_str(), 1);
  error = conversion_error(files);
  EXPECT_NE(error.find("the OFF reader answered something other than glTF"), std::string::npos) << error;

  setenv("TOOND_ASSIMP_CONVERTER",
         fakes.make("liar", "cat >/dev/null; printf 'glTF\\002\\000\\000\\000\\377\\377\\000\\000'").c_str(), 1);
  error = conversion_error(files);
  EXPECT_NE(error.find("cube.off: not a valid glTF binary"), std::string::npos) << error;

  setenv("TOOND_ASSIMP_CONVERTER", fakes.make("refuse", "cat >/dev/null; echo 'no such thing' >&2; exit 1").c_str(), 1);
  error = conversion_error(files);
  EXPECT_NE(error.find("cube.off: no such thing"), std::string::npos) << error;

  // A hang ends at the import's own time limit.
  setenv("TOOND_ASSIMP_CONVERTER", fakes.make("hang", "exec sleep 60").c_str(), 1);
  ImportLimits limits;
  limits.max_seconds = 1.0;
  const auto started = std::chrono::steady_clock::now();
  error = conversion_error(files, limits);
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(10));
  EXPECT_NE(error.find("took longer than"), std::string::npos) << error;

  setenv("TOOND_ASSIMP_CONVERTER", "/nonexistent/toond-assimp-convert", 1);
  error = conversion_error(files);
  EXPECT_NE(error.find("cannot be started"), std::string::npos) << error;
  // The client learns which helper, not where the daemon keeps it.
  EXPECT_NE(error.find("toond-assimp-convert"), std::string::npos) << error;
  EXPECT_EQ(error.find("/nonexistent"), std::string::npos) << error;
}

// A Blitz3D B3D file written here chunk by chunk: one triangle on the
// root node, whose position is keyed at `frames` (1 = the first frame),
// in a clip its ANIM chunk says lasts `stated_frames` at `fps`.
class B3dWriter {
 public:
  std::string file(const std::vector<std::pair<int, glm::vec3>>& keys, int stated_frames, float fps) {
    std::string node = text("root") + floats({0, 0, 0, 1, 1, 1, 1, 0, 0, 0});
    node += chunk("ANIM", ints({0, stated_frames}) + floats({fps}));
    const std::string vertices = ints({0, 0, 0}) + floats({0, 0, 0, 1, 0, 0, 0, 1, 0});
    node += chunk("MESH", ints({-1}) + chunk("VRTS", vertices) + chunk("TRIS", ints({0, 0, 1, 2})));
    std::string keyed = ints({1});
    for (const auto& [frame, position] : keys) keyed += ints({frame}) + floats({position.x, position.y, position.z});
    node += chunk("KEYS", keyed);
    const std::string brush = ints({0}) + text("paint") + floats({1, 1, 1, 1, 0}) + ints({1, 0});
    return chunk("BB3D", ints({1}) + chunk("BRUS", brush) + chunk("NODE", node));
  }

 private:
  static std::string chunk(const char* tag, const std::string& body) {
    return tag + ints({static_cast<int>(body.size())}) + body;
  }
  static std::string text(const std::string& s) { return s + '\0'; }
  static std::string ints(std::initializer_list<int> values) {
    std::string out;
    for (const int v : values) out.append(reinterpret_cast<const char*>(&v), 4);
    return out;
  }
  static std::string floats(std::initializer_list<float> values) {
    std::string out;
    for (const float v : values) out.append(reinterpret_cast<const char*>(&v), 4);
    return out;
  }
};

const std::filesystem::path kMinetest = TOOND_EXPORTED_DIR "/minetest";

Model minetest_player() {
  return import_bundle(make_bundle({{"character.b3d", read_file(kMinetest / "character.b3d")},
                                    {"character.png", read_file(kMinetest / "character.png")}}));
}

// Minetest's player (tests/exported/minetest): a key one frame past its
// clip's stated 220 frames, which assimp's validation refuses, is read
// with the clip running to that key, its frames counted from 0 as the game
// counts them, at the file's 60 frames a second, and the skin the game gives
// it from its code is the upload's one image.
TEST_F(AssimpImport, MinetestsPlayerComesWithItsClipFrameRateAndSkin) {
  const Model model = minetest_player();
  expect_well_formed(model);
  ASSERT_TRUE(model.rig);
  ASSERT_EQ(model.rig->clips.size(), 1u);
  const Clip& clip = model.rig->clips[0];
  ASSERT_TRUE(clip.frame_rate);
  EXPECT_EQ(*clip.frame_rate, 60.0);
  EXPECT_NEAR(clip.duration, 220.0 / 60.0, 1e-6);
  EXPECT_TRUE(has_warning(model, "character.b3d: clip 'anim' has keys up to 221 ticks, past the 220 its file states"))
      << warnings_of(model);
  EXPECT_TRUE(has_warning(model, "B3D frames count from 1; frame 1 is taken as time 0")) << warnings_of(model);
  EXPECT_TRUE(has_warning(model, "drawn with 'character.png', the upload's one image")) << warnings_of(model);
  ASSERT_EQ(model.textures.size(), 1u);
  for (const Material& material : model.materials) EXPECT_EQ(material.diffuse_texture, 0);
}

// The same character as Blender writes it from the .blend the B3D came
// from (30 frames a second, frames 0-220): at each frame of every action
// Minetest plays, the B3D's vertices are where Blender's glTF puts them.
TEST_F(AssimpImport, MinetestsPlayerPosesLikeBlendersGltfOfTheSameFileFrameForFrame) {
  const Model b3d = minetest_player();
  const Model gltf =
      import_bundle(make_bundle({{"character_blender.glb", read_file(kMinetest / "character_blender.glb")}}));
  ASSERT_TRUE(b3d.rig && gltf.rig);
  ASSERT_EQ(gltf.rig->clips.size(), 1u);
  EXPECT_FALSE(gltf.rig->clips[0].frame_rate);  // glTF keys by seconds
  const std::vector<glm::dvec3> rest = test_checks::posed_points(gltf, 0, 0.0);
  for (const int frame : {0, 40, 79, 81, 120, 160, 162, 166, 168, 173, 178, 187, 189, 194, 198, 200, 210, 219, 220}) {
    const std::vector<glm::dvec3> ours = test_checks::posed_points(b3d, 0, frame / 60.0);
    const std::vector<glm::dvec3> blender = test_checks::posed_points(gltf, 0, frame / 30.0);
    EXPECT_LT(test_checks::farthest_from(ours, blender), 1e-4) << "frame " << frame;
    EXPECT_LT(test_checks::farthest_from(blender, ours), 1e-4) << "frame " << frame;
  }
  // The comparison sees poses: walking is not standing.
  EXPECT_GT(test_checks::farthest_from(test_checks::posed_points(gltf, 0, 173 / 30.0), rest), 0.5);
}

// Framing over a range of the clip (pose.h): the walk (frames 168-187) of
// a timeline that also sits and lies down is framed by the walk alone,
// tighter than the whole clip, and holds every pose of the walk.
TEST_F(AssimpImport, MinetestsWalkIsFramedByTheWalkAlone) {
  const Model model = minetest_player();
  ASSERT_TRUE(model.rig);
  const ClipRange walk{168.0 / 60.0, 187.0 / 60.0};
  const ClipFraming whole = frame_clip(model.mesh, *model.rig, 0);
  const ClipFraming walking = frame_clip(model.mesh, *model.rig, 0, walk);
  const ClipFraming again = frame_clip(model.mesh, *model.rig, 0, whole_clip(model.rig->clips[0]));
  EXPECT_EQ(again.bounds.min, whole.bounds.min);
  EXPECT_EQ(again.bounds.max, whole.bounds.max);
  const auto extent = [](const Bounds& b) { return glm::length(b.max - b.min); };
  EXPECT_LT(extent(walking.bounds), 0.8 * extent(whole.bounds));
  const auto inside = [](const Bounds& b, const glm::vec3& p) {
    return glm::all(glm::greaterThanEqual(p, b.min - 1e-4f)) && glm::all(glm::lessThanEqual(p, b.max + 1e-4f));
  };
  for (int step = 0; step <= 38; ++step) {
    const double time = walk.start + (walk.end - walk.start) * step / 38.0;
    const PosedVertices posed =
        pose_vertices(model.mesh, *model.rig, pose_nodes(*model.rig, &model.rig->clips[0], time));
    for (const glm::vec3& p : posed.positions) ASSERT_TRUE(inside(walking.bounds, p)) << "at " << time << " s";
  }
  // Lying down (frame 164) leaves the walk's frame.
  const PosedVertices lying =
      pose_vertices(model.mesh, *model.rig, pose_nodes(*model.rig, &model.rig->clips[0], 164.0 / 60.0));
  EXPECT_FALSE(std::all_of(lying.positions.begin(), lying.positions.end(),
                           [&](const glm::vec3& p) { return inside(walking.bounds, p); }));
}

TEST_F(AssimpImport, AB3dKeyPastItsClipsStatedLengthLengthensTheClip) {
  const std::string file = B3dWriter().file({{1, {0, 0, 0}}, {6, {1, 0, 0}}, {12, {2, 0, 0}}}, 10, 25.0f);
  const Model model = import_bundle(make_bundle({{"slide.b3d", file}}));
  ASSERT_TRUE(model.rig);
  ASSERT_EQ(model.rig->clips.size(), 1u);
  const Clip& clip = model.rig->clips[0];
  EXPECT_NEAR(clip.duration, 11.0 / 25.0, 1e-6);  // frames 1-12, from time 0
  ASSERT_TRUE(clip.frame_rate);
  EXPECT_EQ(*clip.frame_rate, 25.0);
  EXPECT_TRUE(has_warning(model, "slide.b3d: clip 'anim' has keys up to 12 ticks, past the 10 its file states"))
      << warnings_of(model);
  const glm::dvec3 start = test_checks::posed_points(model, 0, 0.0)[0];
  const glm::dvec3 end = test_checks::posed_points(model, 0, 11.0 / 25.0 - 1e-9)[0];
  EXPECT_NEAR(glm::length(end - start), 2.0, 1e-3);
}

TEST_F(AssimpImport, AClipThatStatesNoSpeedPlaysATickASecondWithoutAFrameRate) {
  const std::string file = B3dWriter().file({{1, {0, 0, 0}}, {5, {1, 0, 0}}}, 4, 0.0f);
  const Model model = import_bundle(make_bundle({{"still.b3d", file}}));
  ASSERT_TRUE(model.rig);
  EXPECT_NEAR(model.rig->clips[0].duration, 4.0, 1e-6);
  EXPECT_FALSE(model.rig->clips[0].frame_rate);
  EXPECT_TRUE(has_warning(model, "still.b3d: clip 'anim' states no speed: it plays one key tick a second"))
      << warnings_of(model);
}

// Mending a clip's length lets nothing else through: the mended file still
// meets assimp's validation and the daemon's own glTF checks.
TEST_F(AssimpImportErrors, AMendedClipStillMeetsEveryOtherCheck) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::string not_finite =
      conversion_error({{"nan.b3d", B3dWriter().file({{1, {0, 0, 0}}, {12, {nan, 0, 0}}}, 10, 25.0f)}});
  EXPECT_NE(not_finite.find("nan.b3d: animation 0 sampler 0 output holds a value that is not finite"),
            std::string::npos)
      << not_finite;
  std::string file = B3dWriter().file({{1, {0, 0, 0}}, {12, {1, 0, 0}}}, 10, 25.0f);
  const std::size_t tris = file.find("TRIS");
  ASSERT_NE(tris, std::string::npos);
  file[tris + 16] = 7;  // the triangle's second corner: vertex 7 of 3
  const std::string index = conversion_error({{"index.b3d", file}});
  EXPECT_NE(index.find("index.b3d: B3D Importer - error in B3D file data: Bad triangle index"), std::string::npos)
      << index;
}

// `creases: auto` draws crease lines on what a viewer would call a
// hard-edged model: a CAD part of curved patches meeting at sharp edges
// (CGAL's copies of the classic fandisk and two machined parts, OFF files
// without normals no one here made, tests/exported/cgal) is hard-edged at
// the default crease angle; a smooth scan (the shared Stanford bunny and
// armadillo) and a finely tessellated sphere are not.
const std::filesystem::path kCgal = TOOND_EXPORTED_DIR "/cgal";
constexpr double kDefaultCreaseAngle = 40.0;

class CreaseDecision : public ::testing::Test {
 protected:
  void SetUp() override { setenv("TOOND_ASSIMP_CONVERTER", TOOND_ASSIMP_CONVERTER_PATH, 1); }
};

CreaseProfile creases_of(const std::string& name, const std::string& bytes) {
  const Model model = import_bundle(make_bundle({{name, bytes}}));
  const CreaseProfile& c = model.mesh.creases;
  std::printf("%s: edge length creased %.4f, surface beside crease lines %.4f\n", name.c_str(),
              c.at(kDefaultCreaseAngle), c.lines_area(kDefaultCreaseAngle));
  return c;
}

// A UV sphere of `rings` × 2·`rings` quads, positions and faces only.
std::string sphere_obj(int rings) {
  std::ostringstream obj;
  const double pi = std::acos(-1.0);
  for (int r = 0; r <= rings; ++r) {
    for (int s = 0; s < 2 * rings; ++s) {
      const double theta = pi * r / rings, phi = pi * s / rings;
      obj << "v " << std::sin(theta) * std::cos(phi) << " " << std::cos(theta) << " " << std::sin(theta) * std::sin(phi)
          << "\n";
    }
  }
  const auto at = [rings](int r, int s) { return r * 2 * rings + (s % (2 * rings)) + 1; };
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < 2 * rings; ++s) {
      obj << "f " << at(r, s) << " " << at(r + 1, s) << " " << at(r + 1, s + 1) << " " << at(r, s + 1) << "\n";
    }
  }
  return obj.str();
}

TEST_F(CreaseDecision, CadPartsOfCurvedPatchesAreHardEdged) {
  for (const char* name : {"fandisk.off", "joint.off", "part.off"}) {
    EXPECT_TRUE(creases_of(name, read_file(kCgal / name)).hard_edged(kDefaultCreaseAngle)) << name;
  }
}

TEST_F(CreaseDecision, ASmoothScanOrASphereIsNot) {
  EXPECT_FALSE(creases_of("sphere.obj", sphere_obj(48)).hard_edged(kDefaultCreaseAngle));
  TOOND_REQUIRE_SHARED_MODELS();
  for (const char* path : {"stanford-bunny/stanford-bunny.obj", "armadillo/armadillo.obj", "spot/spot.obj",
                           "blub/blub_triangulated.obj", "bob/bob_tri.obj", "utah-teapot/teapot.obj"}) {
    const std::filesystem::path file = test::shared_models_dir() / path;
    EXPECT_FALSE(creases_of(file.filename().string(), read_file(file)).hard_edged(kDefaultCreaseAngle)) << path;
  }
}

}  // namespace
}  // namespace toond::scene
