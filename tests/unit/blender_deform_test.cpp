// Blender's rigs posed here at full detail against the mesh Blender deforms
// itself at the same frame (its OBJ export of the evaluated mesh): the two
// rigs of issue 43 (tests/exported/blender/make_bending_rigs.py) as glTF
// and FBX at both peaks of the bend and between keys, and the conformance
// set (make_conformance.py) as glTF, FBX and COLLADA at frame 9. Blender's
// glTF puts frame F at F/24 s, its FBX at (F - 1)/24 s.
#include <gtest/gtest.h>

#include <stdlib.h>

#include <cctype>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "model_checks.h"
#include "pose_checks.h"
#include "scene/import/bundle_import.h"
#include "support/shared_models.h"

namespace toond::scene {
namespace {

const std::filesystem::path kDeformedByBlender = TOOND_EXPORTED_DIR "/blender";

struct DeformCase {
  const char* file;
  const char* clip;
  int frame;  // the scene frame Blender wrote the OBJ at
  const char* obj;
};

// Seconds of `frame` in the file: glTF and COLLADA keep frame F at F/24 s,
// FBX starts the take (frame 1) at 0.
double deform_time(const DeformCase& c) {
  const bool fbx = std::string(c.file).ends_with(".fbx");
  return (fbx ? c.frame - 1 : c.frame) / 24.0;
}

double obj_diagonal(const std::vector<glm::dvec3>& points) {
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const glm::dvec3& p : points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return glm::length(hi - lo);
}

class BlenderDeform : public ::testing::TestWithParam<DeformCase> {
 protected:
  void SetUp() override { setenv("TOOND_ASSIMP_CONVERTER", TOOND_ASSIMP_CONVERTER_PATH, 1); }
};

// Every vertex within 1e-4 of the model's size of Blender's (the OBJ's six
// decimals and the exporters' float keys are some 1e-6 m off), while the
// clip's first pose, where nothing is bent, is well away from it.
TEST_P(BlenderDeform, PosesWhereBlenderDeformsIt) {
  const DeformCase& c = GetParam();
  const Model model = import_bundle(test_checks::make_bundle({{c.file, test::read_file(kDeformedByBlender / c.file)}}));
  ASSERT_TRUE(model.rig);
  const Rig& rig = *model.rig;
  const std::optional<std::size_t> clip =
      std::string(c.clip).empty() ? std::optional<std::size_t>(0) : rig.find_clip(c.clip);
  ASSERT_TRUE(clip) << rig.clip_names();
  const std::vector<glm::dvec3> blender = test_checks::obj_positions(test::read_file(kDeformedByBlender / c.obj));
  ASSERT_GT(blender.size(), 100u);
  const double tolerance = 1e-4 * obj_diagonal(blender);
  const std::vector<glm::dvec3> ours = test_checks::posed_points(model, *clip, deform_time(c));
  EXPECT_LT(test_checks::farthest_from(ours, blender), tolerance);
  EXPECT_LT(test_checks::farthest_from(blender, ours), tolerance);
  const std::vector<glm::dvec3> unbent =
      test_checks::posed_points(model, *clip, deform_time({c.file, c.clip, 1, c.obj}));
  EXPECT_GT(test_checks::farthest_from(blender, unbent), 100 * tolerance);
}

std::string deform_case_name(const ::testing::TestParamInfo<DeformCase>& info) {
  std::string name = std::string(info.param.file) + "_f" + std::to_string(info.param.frame);
  for (char& ch : name) {
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  }
  return name;
}

INSTANTIATE_TEST_SUITE_P(Issue43Rigs, BlenderDeform,
                         ::testing::Values(DeformCase{"bending_arm.glb", "Bend", 7, "bending_arm_f07.obj"},
                                           DeformCase{"bending_arm.glb", "Bend", 10, "bending_arm_f10.obj"},
                                           DeformCase{"bending_arm.glb", "Bend", 19, "bending_arm_f19.obj"},
                                           DeformCase{"bending_arm.fbx", "Bend", 7, "bending_arm_f07.obj"},
                                           DeformCase{"bending_arm.fbx", "Bend", 10, "bending_arm_f10.obj"},
                                           DeformCase{"bending_arm.fbx", "Bend", 19, "bending_arm_f19.obj"},
                                           DeformCase{"turned_limb.glb", "Bend", 7, "turned_limb_f07.obj"},
                                           DeformCase{"turned_limb.glb", "Bend", 10, "turned_limb_f10.obj"},
                                           DeformCase{"turned_limb.glb", "Bend", 19, "turned_limb_f19.obj"},
                                           DeformCase{"turned_limb.fbx", "Bend", 7, "turned_limb_f07.obj"},
                                           DeformCase{"turned_limb.fbx", "Bend", 10, "turned_limb_f10.obj"},
                                           DeformCase{"turned_limb.fbx", "Bend", 19, "turned_limb_f19.obj"}),
                         deform_case_name);

// COLLADA is left out where Blender's own file is wrong (an armature object
// with a transform: make_conformance.py) or toond cannot read it yet
// (morph_skin, constant: tests/conformance/cases.json); FBX and COLLADA for
// `eight`, whose readers keep four influences.
INSTANTIATE_TEST_SUITE_P(ConformanceSet, BlenderDeform,
                         ::testing::Values(DeformCase{"conf_tentacle.glb", "Move", 9, "conf_tentacle_f09.obj"},
                                           DeformCase{"conf_tentacle.fbx", "Move", 9, "conf_tentacle_f09.obj"},
                                           DeformCase{"conf_tentacle.dae", "", 9, "conf_tentacle_f09.obj"},
                                           DeformCase{"conf_turned.glb", "Move", 9, "conf_turned_f09.obj"},
                                           DeformCase{"conf_turned.fbx", "Move", 9, "conf_turned_f09.obj"},
                                           DeformCase{"conf_stretched.glb", "Move", 9, "conf_stretched_f09.obj"},
                                           DeformCase{"conf_stretched.fbx", "Move", 9, "conf_stretched_f09.obj"},
                                           DeformCase{"conf_parented.glb", "Move", 9, "conf_parented_f09.obj"},
                                           DeformCase{"conf_parented.fbx", "Move", 9, "conf_parented_f09.obj"},
                                           DeformCase{"conf_offset_mesh.glb", "Move", 9, "conf_offset_mesh_f09.obj"},
                                           DeformCase{"conf_offset_mesh.fbx", "Move", 9, "conf_offset_mesh_f09.obj"},
                                           DeformCase{"conf_offset_mesh.dae", "", 9, "conf_offset_mesh_f09.obj"},
                                           DeformCase{"conf_branches.glb", "Move", 9, "conf_branches_f09.obj"},
                                           DeformCase{"conf_branches.fbx", "Move", 9, "conf_branches_f09.obj"},
                                           DeformCase{"conf_branches.dae", "", 9, "conf_branches_f09.obj"},
                                           DeformCase{"conf_eight.glb", "Move", 9, "conf_eight_f09.obj"},
                                           DeformCase{"conf_cubic.glb", "Move", 9, "conf_cubic_f09.obj"},
                                           DeformCase{"conf_cubic.fbx", "Move", 9, "conf_cubic_f09.obj"},
                                           DeformCase{"conf_cubic.dae", "", 9, "conf_cubic_f09.obj"},
                                           DeformCase{"conf_step.glb", "Move", 9, "conf_step_f09.obj"},
                                           DeformCase{"conf_step.fbx", "Move", 9, "conf_step_f09.obj"},
                                           DeformCase{"conf_step.dae", "", 9, "conf_step_f09.obj"},
                                           DeformCase{"conf_constant.glb", "Move", 9, "conf_constant_f09.obj"},
                                           DeformCase{"conf_constant.fbx", "Move", 9, "conf_constant_f09.obj"},
                                           DeformCase{"conf_scale_keys.glb", "Move", 9, "conf_scale_keys_f09.obj"},
                                           DeformCase{"conf_scale_keys.fbx", "Move", 9, "conf_scale_keys_f09.obj"},
                                           DeformCase{"conf_scale_keys.dae", "", 9, "conf_scale_keys_f09.obj"},
                                           DeformCase{"conf_morph_skin.glb", "Move", 9, "conf_morph_skin_f09.obj"},
                                           DeformCase{"conf_morph_skin.fbx", "Move", 9, "conf_morph_skin_f09.obj"},
                                           DeformCase{"conf_skinned_node_moved.glb", "Move", 9, "conf_turned_f09.obj"}),
                         deform_case_name);

}  // namespace
}  // namespace toond::scene
