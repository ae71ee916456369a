// Compressed glTF through the daemon: meshopt and Draco uploads render like
// their plain twin, and Draco data that breaks the decoder (garbage, or a
// decoder that crashes outright) is a 422 naming the primitive while the
// daemon keeps serving.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "scene/import/obj_import.h"
#include "support/generated_models.h"
#include "support/gltf_draco_writer.h"
#include "support/gltf_meshopt_writer.h"
#include "support/gltf_twin.h"
#include "support/gltf_writer.h"
#include "test_client.h"

namespace toond::test {
namespace {

using nlohmann::json;

GltfParts sphere_parts() {
  scene::Bundle bundle;
  bundle.add("sphere.obj", sphere_obj(48, 24));
  return build_gltf(gltf_twin(scene::import_obj_bundle(bundle), bundle));
}

httplib::Result post_glb(httplib::Client& client, const GltfParts& parts) {
  const std::string glb = pack_gltf(parts, GltfForm::Glb)[0].second;
  return client.Post("/models", httplib::MultipartFormDataItems{{"file", glb, "model.glb", "model/gltf-binary"}});
}

// The Draco data of the first primitive overwritten with noise.
GltfParts with_garbage_draco(GltfParts parts) {
  const json& extension = parts.json["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"];
  const json& view = parts.json["bufferViews"][extension["bufferView"].get<std::size_t>()];
  const std::size_t offset = view["byteOffset"];
  const std::size_t length = view["byteLength"];
  for (std::size_t i = 0; i < length; ++i) parts.bin[offset + i] = static_cast<char>((i * 131 + 7) & 0xff);
  return parts;
}

void expect_alive(httplib::Client& client) {
  auto health = client.Get("/healthz");
  ASSERT_TRUE(health) << "the daemon does not answer";
  EXPECT_EQ(health->status, 200);
  render_ok(client, {{"width", 64}, {"height", 64}});
}

class GltfCompression : public SharedDaemonTest {};

TEST_F(GltfCompression, MeshoptAndDracoUploadsRenderLikeThePlainOne) {
  auto client = daemon().client();
  const GltfParts plain = sphere_parts();
  const json look = {{"width", 160}, {"height", 160}, {"camera", {{"yaw", 30}, {"pitch", 20}}}};
  std::vector<image::Image> images;
  std::vector<int> triangles;
  for (const GltfParts& parts : {plain, meshopt_compress(plain), draco_compress(plain)}) {
    auto res = post_glb(client, parts);
    ASSERT_TRUE(res);
    ASSERT_TRUE(res->status == 200 || res->status == 201) << res->body;
    const json model = json::parse(res->body);
    triangles.push_back(model["triangles"].get<int>());
    json params = look;
    params["model"] = model["id"];
    images.push_back(render_ok(client, params));
  }
  for (std::size_t k = 1; k < images.size(); ++k) {
    EXPECT_EQ(triangles[k], triangles[0]);
    ASSERT_EQ(images[k].rgba.size(), images[0].rgba.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < images[0].rgba.size(); ++i) {
      differing += std::abs(int(images[k].rgba[i]) - int(images[0].rgba[i])) > 24 ? 1 : 0;
    }
    EXPECT_LT(differing, images[0].rgba.size() / 200) << "upload " << k << " renders differently";
  }
}

TEST_F(GltfCompression, GarbageDracoDataIsA422NamingThePrimitiveAndTheDaemonStaysUp) {
  auto client = daemon().client();
  auto res = post_glb(client, with_garbage_draco(draco_compress(sphere_parts())));
  ASSERT_TRUE(res) << "the daemon does not answer";
  EXPECT_EQ(res->status, 422) << res->body;
  const json error = error_of(res);
  EXPECT_EQ(error["code"], "bad_bundle");
  EXPECT_EQ(error["path"], "model.glb");
  EXPECT_NE(
      error["message"].get<std::string>().find("mesh 0 primitive 0 (KHR_draco_mesh_compression) cannot be decoded"),
      std::string::npos)
      << error;
  expect_alive(client);
}

TEST_F(GltfCompression, ATruncatedMeshoptStreamIsA422NamingTheView) {
  auto client = daemon().client();
  GltfParts parts = meshopt_compress(sphere_parts());
  json& extension = parts.json["bufferViews"][0]["extensions"]["EXT_meshopt_compression"];
  extension["byteLength"] = extension["byteLength"].get<std::size_t>() / 2;
  auto res = post_glb(client, parts);
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 422) << res->body;
  EXPECT_NE(
      error_of(res)["message"].get<std::string>().find("buffer view 0 (EXT_meshopt_compression) cannot be decoded"),
      std::string::npos)
      << res->body;
  expect_alive(client);
}

// A decoder that crashes on every input, in place of the real one: the
// daemon answers 422 and goes on.
TEST(GltfCompressionDaemon, ADecoderCrashIsA422AndTheDaemonStaysUp) {
  const std::filesystem::path dir = make_temp_dir("toond-crashing-draco");
  const std::filesystem::path decoder = dir / "toond-draco-decode";
  std::ofstream(decoder) << "#!/bin/sh\nkill -SEGV $$\n";
  std::filesystem::permissions(decoder, std::filesystem::perms::owner_all);
  setenv("TOOND_DRACO_DECODER", decoder.c_str(), 1);
  Daemon daemon;
  unsetenv("TOOND_DRACO_DECODER");
  auto client = daemon.client();
  auto res = post_glb(client, draco_compress(sphere_parts()));
  ASSERT_TRUE(res) << "the daemon does not answer";
  EXPECT_EQ(res->status, 422) << res->body;
  EXPECT_NE(res->body.find("the decoder crashed (SIGSEGV)"), std::string::npos) << res->body;
  expect_alive(client);
  daemon.stop();
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace toond::test
