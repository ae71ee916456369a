// glTF uploads render like the OBJ they were made from: each shared OBJ
// model's glTF twin (written here from the OBJ import, as a .glb with its
// images embedded) goes through the same upload and render as the OBJ
// folder, and the two images must match within a few stray pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "image/png_codec.h"
#include "scene/import/obj_import.h"
#include "support/gltf_twin.h"
#include "support/image_checks.h"
#include "support/shared_models.h"
#include "test_client.h"

namespace toond::test {
namespace {

using nlohmann::json;

class GltfRender : public SharedDaemonTest, public ::testing::WithParamInterface<const char*> {};

TEST_P(GltfRender, GlbTwinRendersLikeTheObj) {
  TOOND_REQUIRE_SHARED_MODELS();
  const std::filesystem::path dir = shared_models_dir() / GetParam();
  scene::Bundle bundle;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file()) {
      bundle.add(std::filesystem::relative(entry.path(), dir).generic_string(), read_file(entry.path()));
    }
  }
  const std::string glb = write_gltf(gltf_twin(scene::import_obj_bundle(bundle), bundle), GltfForm::Glb)[0].second;

  auto client = daemon().client();
  auto obj_upload = upload_model_folder(client, dir);
  ASSERT_TRUE(obj_upload && (obj_upload->status == 200 || obj_upload->status == 201));
  auto glb_upload =
      client.Post("/models", httplib::MultipartFormDataItems{{"file", glb, "model.glb", "model/gltf-binary"}});
  ASSERT_TRUE(glb_upload);
  ASSERT_TRUE(glb_upload->status == 200 || glb_upload->status == 201) << glb_upload->body;

  // The twin carries no specular colour (glTF has no Phong Ks), so the
  // highlight is off in both.
  const json look = {
      {"width", 320}, {"height", 320}, {"camera", {{"yaw", -140}, {"pitch", 12}}}, {"specular", {{"enabled", false}}}};
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

// A unit quad facing +Z with one material, its texture `png`.
std::string quad_glb(const std::string& png, const nlohmann::json& material_json) {
  GltfPrimitive quad;
  quad.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  quad.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  quad.texcoords = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};
  quad.indices = {0, 1, 2, 0, 2, 3};
  quad.material = 0;
  GltfDocument doc;
  doc.meshes = {{quad}};
  doc.images = {{png, "image/png", "cutout.png"}};
  doc.materials = {{glm::vec4(0.8f, 0.2f, 0.2f, 1.0f), 0, -1, material_json}};
  return write_gltf(doc, GltfForm::Glb)[0].second;
}

// 64×64: the left half fully transparent, the right half opaque white.
std::string half_transparent_png() {
  image::Image img;
  img.width = img.height = 64;
  img.rgba.assign(64 * 64 * 4, 255);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 32; ++x) img.rgba[(static_cast<std::size_t>(y) * 64 + x) * 4 + 3] = 0;
  return image::encode_png(img);
}

// 64×64: opaque white only in columns 32..61. The clear columns at both
// ends keep a repeating texture's filtering at u = 0 from reaching the
// opaque half, so the quad's cut-away edge is cut away to its last pixel.
std::string opaque_middle_right_png() {
  image::Image img;
  img.width = img.height = 64;
  img.rgba.assign(64 * 64 * 4, 255);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x)
      if (x < 32 || x >= 62) img.rgba[(static_cast<std::size_t>(y) * 64 + x) * 4 + 3] = 0;
  return image::encode_png(img);
}

std::string upload_glb(httplib::Client& client, const std::string& glb) {
  auto res = client.Post("/models", httplib::MultipartFormDataItems{{"file", glb, "model.glb", "model/gltf-binary"}});
  EXPECT_TRUE(res && (res->status == 200 || res->status == 201)) << (res ? res->body : "no answer");
  return res ? json::parse(res->body).value("id", "") : "";
}

// Share of the quad's left and right thirds (rows through the middle) that
// show the blue background.
std::pair<double, double> background_in_thirds(const image::Image& img) {
  std::size_t left = 0, right = 0, n = 0;
  for (int y = 48; y < 80; ++y) {
    for (int x = 0; x < 128; ++x) {
      const std::uint8_t* p = &img.rgba[(static_cast<std::size_t>(y) * 128 + x) * 4];
      const bool blue = p[0] < 30 && p[1] < 30 && p[2] > 200;
      if (x >= 20 && x < 40) left += blue ? 1 : 0, ++n;
      if (x >= 88 && x < 108) right += blue ? 1 : 0;
    }
  }
  return {static_cast<double>(left) / n, static_cast<double>(right) / n};
}

class GltfMaterials : public SharedDaemonTest {};

// glTF alphaMode MASK: where the texture's alpha is under the cutoff the
// surface is not drawn, so the background shows; OPAQUE draws it all.
TEST_F(GltfMaterials, MaskCutsTheShapeOutOfTheTexture) {
  auto client = daemon().client();
  const json look = {{"width", 128},
                     {"height", 128},
                     {"background", {0, 0, 1}},
                     {"outline", {{"enabled", false}}},
                     {"shading", {{"mode", "flat"}}},
                     {"camera", {{"yaw", 0}, {"pitch", 0}}}};
  json params = look;
  params["model"] = upload_glb(client, quad_glb(half_transparent_png(), {{"alphaMode", "MASK"}}));
  const auto [masked_left, masked_right] = background_in_thirds(render_ok(client, params));
  EXPECT_GT(masked_left, 0.99);
  EXPECT_LT(masked_right, 0.01);
  params["model"] = upload_glb(client, quad_glb(half_transparent_png(), json::object()));
  const auto [opaque_left, opaque_right] = background_in_thirds(render_ok(client, params));
  EXPECT_LT(opaque_left, 0.01);
  EXPECT_LT(opaque_right, 0.01);
}

// The data layers test a masked material's alpha like the main pass: where
// it is cut away they hold background (depth 65535, read here as 255 in 8
// bits; normal and id transparent), beside it the quad.
TEST_F(GltfMaterials, DataLayersFollowWhatTheMaskLeaves) {
  auto client = daemon().client();
  const std::string masked = upload_glb(client, quad_glb(half_transparent_png(), {{"alphaMode", "MASK"}}));
  for (const char* output : {"depth", "normal", "id"}) {
    const json params = {
        {"model", masked}, {"width", 128}, {"height", 128}, {"output", output}, {"camera", {{"yaw", 0}, {"pitch", 0}}}};
    const image::Image layer = render_ok(client, params);
    const bool depth = std::string(output) == "depth";
    auto background = [&](int x, int y) {
      const std::uint8_t* p = layer.pixel(x, y);
      return depth ? p[0] == 255 : p[3] == 0;
    };
    std::size_t cut_shown = 0, kept_shown = 0;
    for (int y = 48; y < 80; ++y) {
      for (int x = 20; x < 40; ++x) cut_shown += !background(x, y);
      for (int x = 88; x < 108; ++x) kept_shown += !background(x, y);
    }
    EXPECT_EQ(cut_shown, 0u) << output << ": the cut-away half";
    EXPECT_EQ(kept_shown, 32u * 20u) << output << ": the half the mask keeps";
  }
}

// Outline-coloured pixels in the half of the image (less a margin at the
// middle) where the half transparent quad is cut away: the left half seen
// from the front, the right half seen from behind.
std::size_t outline_pixels_where_cut_away(const image::Image& img, bool from_behind) {
  std::size_t red = 0;
  const int half = img.width / 2 - 6;
  for (int y = 0; y < img.height; ++y) {
    for (int x = from_behind ? img.width - half : 0; x < (from_behind ? img.width : half); ++x) {
      const std::uint8_t* p = &img.rgba[(static_cast<std::size_t>(y) * img.width + x) * 4];
      red += (p[0] > 100 && p[1] < 80 && p[2] < 80) ? 1 : 0;
    }
  }
  return red;
}

// Every outline method tests a masked material's alpha like the main pass:
// no line runs round the quad's cut-away half. An opaque quad has one. The
// wireframe draws back faces' edges, so it sees the quad from behind.
TEST_F(GltfMaterials, OutlinesFollowWhatTheMaskLeaves) {
  auto client = daemon().client();
  const std::string masked = upload_glb(client, quad_glb(opaque_middle_right_png(), {{"alphaMode", "MASK"}}));
  const std::string opaque = upload_glb(client, quad_glb(opaque_middle_right_png(), json::object()));
  for (const char* method : {"hull", "wireframe", "edges"}) {
    json params = {{"width", 128},
                   {"height", 128},
                   {"background", {0, 0, 1}},
                   {"shading", {{"mode", "flat"}, {"base", "white"}}},
                   {"outline", {{"method", method}, {"width", 3}, {"color", {1, 0, 0}}, {"creases", "never"}}}};
    const bool from_behind = std::string(method) == "wireframe";
    params["camera"] = {{"yaw", from_behind ? 180 : 0}, {"pitch", 0}};
    params["model"] = opaque;
    EXPECT_GT(outline_pixels_where_cut_away(render_ok(client, params), from_behind), 40u)
        << method << ": the opaque quad's outline";
    params["model"] = masked;
    EXPECT_EQ(outline_pixels_where_cut_away(render_ok(client, params), from_behind), 0u) << method;
  }
}

// Mean sRGB level (green) of the floor in front of the quad: the image's
// lower part, in its left and right thirds.
std::pair<double, double> floor_level_in_thirds(const image::Image& img) {
  double left = 0, right = 0;
  std::size_t n = 0;
  for (int y = img.height * 3 / 4; y < img.height - 4; ++y) {
    for (int x = img.width / 6; x < img.width / 3; ++x) {
      left += img.rgba[(static_cast<std::size_t>(y) * img.width + x) * 4 + 1];
      right += img.rgba[(static_cast<std::size_t>(y) * img.width + (img.width - 1 - x)) * 4 + 1];
      ++n;
    }
  }
  return {left / n, right / n};
}

// A masked material casts a shadow only where the main pass draws it: the
// half-cut quad's shadow on the floor in front of it covers the right half
// only; the opaque quad's covers both.
TEST_F(GltfMaterials, MaskedMaterialsCastShadowsOnlyWhereTheyAreDrawn) {
  auto client = daemon().client();
  json params = {{"width", 128},
                 {"height", 128},
                 {"background", {0, 0, 1}},
                 {"outline", {{"enabled", false}}},
                 {"camera", {{"yaw", 0}, {"pitch", 35}}},
                 {"floor", {{"enabled", true}}},
                 {"shadows", {{"enabled", true}}},
                 {"specular", {{"enabled", false}}},
                 {"lights", {{{"type", "directional"}, {"direction", {0, -1, 0.9}}}}}};
  params["model"] = upload_glb(client, quad_glb(opaque_middle_right_png(), json::object()));
  const auto [opaque_left, opaque_right] = floor_level_in_thirds(render_ok(client, params));
  params["model"] = upload_glb(client, quad_glb(opaque_middle_right_png(), {{"alphaMode", "MASK"}}));
  const auto [masked_left, masked_right] = floor_level_in_thirds(render_ok(client, params));
  // Measured: opaque 120 / 120, masked 217 / 125 (lit floor 217).
  EXPECT_NEAR(opaque_left, opaque_right, 10.0) << "both halves of the opaque quad cast";
  EXPECT_GT(masked_left, masked_right + 50.0) << "the cut half casts no shadow";
  EXPECT_NEAR(masked_right, opaque_right, 10.0) << "the drawn half casts as before";
}

// KHR_materials_unlit: the base colour as it is, whatever the light; the
// same quad lit at a slant falls into a darker band.
TEST_F(GltfMaterials, UnlitShowsTheBaseColourWithoutBands) {
  auto client = daemon().client();
  const std::string white = image::encode_png([] {
    image::Image img;
    img.width = img.height = 4;
    img.rgba.assign(4 * 4 * 4, 255);
    return img;
  }());
  const json look = {{"width", 128},
                     {"height", 128},
                     {"outline", {{"enabled", false}}},
                     {"shading", {{"mode", "cel"}, {"steps", 3}}},
                     {"specular", {{"enabled", false}}},
                     {"rim", {{"enabled", false}}},
                     {"ambient", 0.2},
                     {"camera", {{"yaw", 0}, {"pitch", 0}}},
                     {"lights", {{{"type", "directional"}, {"direction", {-0.95, 0, -0.3}}, {"intensity", 1}}}}};
  json params = look;
  params["model"] = upload_glb(client, quad_glb(white, {{"extensions", {{"KHR_materials_unlit", json::object()}}}}));
  const Rgb unlit = rgb_at(render_ok(client, params), 64, 64);
  params["model"] = upload_glb(client, quad_glb(white, json::object()));
  const Rgb lit = rgb_at(render_ok(client, params), 64, 64);
  // Linear (0.8, 0.2, 0.2), sRGB-encoded on write.
  EXPECT_NEAR(unlit.r, 231, 2);
  EXPECT_NEAR(unlit.g, 124, 2);
  EXPECT_NEAR(unlit.b, 124, 2);
  EXPECT_LT(lit.r + 10, unlit.r) << "the lit quad should sit in a darker band";
}

}  // namespace
}  // namespace toond::test
