// glTF uploads render like the OBJ they were made from: each shared OBJ
// model's glTF twin (written here from the OBJ import, as a .glb with its
// images embedded) goes through the same upload and render as the OBJ
// folder, and the two images must match within a few stray pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

#include "scene/obj_import.h"
#include "support/gltf_twin.h"
#include "support/shared_models.h"
#include "test_client.h"

namespace toond::test {
namespace {

using nlohmann::json;

class GltfRender : public SharedDaemonTest, public ::testing::WithParamInterface<const char*> {};

// Share of pixels whose colour differs by more than `levels` in a channel.
double differing_share(const image::Image& a, const image::Image& b, int levels) {
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    for (std::size_t c = 0; c < 3; ++c) {
      if (std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c])) > levels) {
        ++differing;
        break;
      }
    }
  }
  return static_cast<double>(differing) / static_cast<double>(a.rgba.size() / 4);
}

TEST_P(GltfRender, GlbTwinRendersLikeTheObj) {
  TOOND_REQUIRE_SHARED_MODELS();
  const std::filesystem::path dir = shared_models_dir() / GetParam();
  scene::Bundle bundle;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file()) {
      bundle.add(std::filesystem::relative(entry.path(), dir).generic_string(), read_file(entry.path()));
    }
  }
  const std::string glb =
      write_gltf(gltf_twin(scene::import_obj_bundle(bundle), bundle), GltfForm::Glb)[0].second;

  auto client = daemon().client();
  auto obj_upload = upload_model_folder(client, dir);
  ASSERT_TRUE(obj_upload && (obj_upload->status == 200 || obj_upload->status == 201));
  auto glb_upload = client.Post("/models", httplib::MultipartFormDataItems{{"file", glb, "model.glb", "model/gltf-binary"}});
  ASSERT_TRUE(glb_upload);
  ASSERT_TRUE(glb_upload->status == 200 || glb_upload->status == 201) << glb_upload->body;

  // The twin carries no specular colour (glTF has no Phong Ks), so the
  // highlight is off in both.
  const json look = {{"width", 320}, {"height", 320}, {"camera", {{"yaw", -140}, {"pitch", 12}}},
                     {"specular", {{"enabled", false}}}};
  json obj_params = look;
  obj_params["model"] = json::parse(obj_upload->body)["id"];
  json glb_params = look;
  glb_params["model"] = json::parse(glb_upload->body)["id"];
  const image::Image from_obj = render_ok(client, obj_params);
  const image::Image from_glb = render_ok(client, glb_params);
  ASSERT_EQ(from_obj.rgba.size(), from_glb.rgba.size());
  const double share = differing_share(from_obj, from_glb, 24);
  EXPECT_LT(share, 0.005) << GetParam() << ": " << share * 100 << "% of the pixels differ";
}

INSTANTIATE_TEST_SUITE_P(Shared, GltfRender, ::testing::Values("spot", "kenney-cube-pet-dog", "windmill"));

}  // namespace
}  // namespace toond::test
