// Game files as Debian ships them (tests/exported/<game>/, README.md in each
// says where from) drawn by the default request as their games draw them:
// held against glTF twins of the same files whose materials are set the
// way the game sets them (tests/exported/make_game_twins.py), and against
// what the game shows (see-through texels, solid armour, a matte sleeve,
// clips from the files beside the mesh).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "glb/glb_container.h"
#include "image/png_codec.h"
#include "support/daemon.h"
#include "support/image_checks.h"
#include "support/shared_models.h"
#include "test_client.h"

namespace toond::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const fs::path kExported = TOOND_EXPORTED_DIR;

// A bundle file: its path in the upload and its bytes.
using File = std::pair<std::string, std::string>;

File file_of(const std::string& bundle_path, const fs::path& on_disk) { return {bundle_path, read_file(on_disk)}; }

// Uploads `files` with `query` ("?textures=..."); the answer must be 200/201.
json upload(httplib::Client& client, const std::vector<File>& files, const std::string& query = "") {
  httplib::MultipartFormDataItems items;
  for (const auto& [path, bytes] : files) items.push_back({"file", bytes, path, "application/octet-stream"});
  auto res = client.Post("/models" + query, items);
  if (!res || (res->status != 200 && res->status != 201)) {
    ADD_FAILURE() << "upload failed: " << (res ? res->body : httplib::to_string(res.error()));
    return json::object();
  }
  return json::parse(res->body);
}

std::string warnings_of(const json& answer) { return answer.value("warnings", json::array()).dump(1); }

bool warns(const json& answer, const std::string& words) {
  for (const json& w : answer.value("warnings", json::array())) {
    if (w.get<std::string>().find(words) != std::string::npos) return true;
  }
  return false;
}

// Luminance, 0..255, of an sRGB pixel.
double luma(const image::Image& img, int x, int y) { return 255.0 * luminance(rgb_at(img, x, y)); }

// Of the pixels either image draws the model on (not the background), the
// share whose luminance differs by more than `levels`.
double figure_differing(const image::Image& a, const image::Image& b, double levels) {
  const std::vector<bool> fa = foreground_mask(a);
  const std::vector<bool> fb = foreground_mask(b);
  std::size_t figure = 0;
  std::size_t differing = 0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * a.width + x;
      if (!fa[i] && !fb[i]) continue;
      ++figure;
      differing += std::abs(luma(a, x, y) - luma(b, x, y)) > levels ? 1 : 0;
    }
  }
  return figure == 0 ? 1.0 : static_cast<double>(differing) / figure;
}

// Of the whole image, the share of pixels whose luminance differs by more
// than `levels`.
double image_differing(const image::Image& a, const image::Image& b, double levels) {
  std::size_t differing = 0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) differing += std::abs(luma(a, x, y) - luma(b, x, y)) > levels ? 1 : 0;
  }
  return static_cast<double>(differing) / (static_cast<double>(a.width) * a.height);
}

// The default request's framing distance of a model (its atlas says it).
double framing_distance(httplib::Client& client, const std::string& id) {
  auto res =
      client.Post("/render?atlas=json", json{{"model", id}, {"sheet", {{"frames", 1}}}}.dump(), "application/json");
  if (!res || res->status != 200) {
    ADD_FAILURE() << "atlas: " << (res ? res->body : "no answer");
    return 1.0;
  }
  return json::parse(res->body)["meta"]["camera"]["distance"].get<double>();
}

// Where test images are written to be looked at.
void keep(const image::Image& img, const std::string& name) {
  const fs::path dir = fs::path(testing::TempDir()) / "game_files";
  fs::create_directories(dir);
  std::ofstream(dir / (name + ".png"), std::ios::binary) << image::encode_png(img);
}

class GameFiles : public SharedDaemonTest {
 protected:
  // The game file and its twin drawn by the default request from the front
  // and from behind: at most 2 % of the figure's pixels differ by more than
  // 24 levels.
  void expect_like_twin(const std::string& game_id, const std::string& twin_id, const std::string& name,
                        const json& extra = json::object()) {
    auto client = daemon().client();
    for (const double yaw : {0.0, 180.0}) {
      json request = {{"model", game_id}, {"camera", {{"yaw", yaw}}}};
      request.update(extra);
      const image::Image game = render_ok(client, request);
      request["model"] = twin_id;
      const image::Image twin = render_ok(client, request);
      keep(game, name + "_yaw" + std::to_string(static_cast<int>(yaw)));
      keep(twin, name + "_twin_yaw" + std::to_string(static_cast<int>(yaw)));
      const double share = figure_differing(game, twin, 24.0);
      std::printf("%s yaw %.0f: %.2f %% of the figure (%.2f %% of the image) differs by > 24 levels\n", name.c_str(),
                  yaw, 100.0 * share, 100.0 * image_differing(game, twin, 24.0));
      EXPECT_LE(share, 0.02) << name << " at yaw " << yaw;
    }
  }

  // Close up, at 0.8 of the default framing's distance (about 20 px a
  // texel for these skins): at most 1 % of the image differs by more than
  // 8 levels.
  void expect_like_twin_close_up(const std::string& game_id, const std::string& twin_id, const std::string& name) {
    auto client = daemon().client();
    const double close = 0.8 * framing_distance(client, game_id);
    const image::Image game = render_ok(client, {{"model", game_id}, {"camera", {{"distance", close}}}});
    const image::Image twin = render_ok(client, {{"model", twin_id}, {"camera", {{"distance", close}}}});
    keep(game, name + "_close");
    const double share = image_differing(game, twin, 8.0);
    std::printf("%s close up: %.2f %% of the image differs by > 8 levels\n", name.c_str(), 100.0 * share);
    EXPECT_LE(share, 0.01) << name;
  }
};

json minetest_player(httplib::Client& client) {
  return upload(client, {file_of("character.b3d", kExported / "minetest/character.b3d"),
                         file_of("character.png", kExported / "minetest/character.png")});
}

json minetest_player_twin(httplib::Client& client) {
  return upload(client, {file_of("character_twin.glb", kExported / "minetest/character_twin.glb"),
                         file_of("character.png", kExported / "minetest/character.png")});
}

// Minetest's player: the hat layer's empty texels let the face show (it
// was a black box), the skin is sharp, the cloth matte; held against its
// twin from both sides and close up (about 20 px a texel).
TEST_F(GameFiles, MinetestsPlayerLooksLikeItsTwinFromBothSidesAndCloseUp) {
  auto client = daemon().client();
  const json game = minetest_player(client);
  const json twin = minetest_player_twin(client);
  ASSERT_EQ(game["material_list"].size(), 1u) << game.dump();
  EXPECT_EQ(game["material_list"][0]["alpha"], "mask");
  EXPECT_EQ(game["material_list"][0]["texture"], "character.png");
  EXPECT_TRUE(game["material_list"][0]["matte"].get<bool>());
  expect_like_twin(game["id"], twin["id"], "minetest_player");
  // The look before game files were drawn as their games draw them (the
  // hat layer opaque, the highlight everywhere, the skin smeared) is far
  // from the twin: the comparison sees what changed.
  auto client_before = daemon().client();
  const json before = {{"model", game["id"]},
                       {"materials", {{"Character", {{"alpha", "opaque"}}}}},
                       {"specular", {{"source", "all"}}},
                       {"textures", {{"filter", "linear"}}}};
  EXPECT_GT(figure_differing(render_ok(client_before, before), render_ok(client_before, {{"model", twin["id"]}}), 24.0),
            0.02);

  expect_like_twin_close_up(game["id"], twin["id"], "minetest_player");

  // The face: the head's top quarter of the figure is not a black box.
  const image::Image front = render_ok(client, {{"model", game["id"]}});
  const std::vector<bool> figure = foreground_mask(front);
  int top = front.height;
  int bottom = 0;
  for (int y = 0; y < front.height; ++y) {
    for (int x = 0; x < front.width; ++x) {
      if (!figure[static_cast<std::size_t>(y) * front.width + x]) continue;
      top = std::min(top, y);
      bottom = std::max(bottom, y);
    }
  }
  std::size_t head = 0;
  std::size_t dark = 0;
  for (int y = top; y < top + (bottom - top) / 4; ++y) {
    for (int x = 0; x < front.width; ++x) {
      if (!figure[static_cast<std::size_t>(y) * front.width + x]) continue;
      ++head;
      dark += luma(front, x, y) < 20.0 ? 1 : 0;
    }
  }
  ASSERT_GT(head, 0u);
  EXPECT_LT(static_cast<double>(dark) / head, 0.15) << dark << " of " << head << " head pixels near black";
}

// From behind (yaw 0: the player faces -Z), mid-walk (frame 180 of the
// walk, 168-187), the matte trousers have no white spot; asked for, the
// highlight of every material (the look before) comes back, on about a
// tenth of the figure. Over black, so no pixel of an outline's edge
// blending into the background counts as white.
TEST_F(GameFiles, MinetestsPlayerHasNoHighlightOnItsMatteCloth) {
  auto client = daemon().client();
  const json game = minetest_player(client);
  const auto near_white = [&](const json& extra) {
    json request = {{"model", game["id"]},
                    {"background", {0, 0, 0}},
                    {"camera", {{"yaw", 0.0}}},
                    {"animation", {{"clip", 0}, {"time", 180.0 / 60.0}}}};
    request.update(extra);
    const image::Image img = render_ok(client, request);
    const std::vector<bool> figure = foreground_mask(img);
    std::size_t white = 0;
    for (int y = 0; y < img.height; ++y) {
      for (int x = 0; x < img.width; ++x) {
        const Rgb c = rgb_at(img, x, y);
        white += figure[static_cast<std::size_t>(y) * img.width + x] && std::min({c.r, c.g, c.b}) > 200 ? 1 : 0;
      }
    }
    return static_cast<double>(white) / static_cast<double>(count(figure));
  };
  const double matte = near_white(json::object());
  const double all = near_white({{"specular", {{"source", "all"}}}});
  std::printf("near white: %.2f %% of the figure (specular.source all: %.2f %%)\n", 100.0 * matte, 100.0 * all);
  EXPECT_LE(matte, 0.005);
  EXPECT_GT(all, 0.05);
}

// Minetest's door: its four windows are empty texels of the skin; they
// show what is behind them (the background), as the twin does.
TEST_F(GameFiles, MinetestsDoorShowsThroughItsWindows) {
  auto client = daemon().client();
  const json game = upload(client, {file_of("door_a.b3d", kExported / "minetest/door_a.b3d"),
                                    file_of("doors_door_wood.png", kExported / "minetest/doors_door_wood.png")});
  const json twin = upload(client, {file_of("door_a_twin.glb", kExported / "minetest/door_a_twin.glb"),
                                    file_of("doors_door_wood.png", kExported / "minetest/doors_door_wood.png")});
  expect_like_twin(game["id"], twin["id"], "minetest_door");
  expect_like_twin_close_up(game["id"], twin["id"], "minetest_door");
  const image::Image front = render_ok(client, {{"model", game["id"]}});
  const std::vector<bool> figure = foreground_mask(front);
  int left = front.width, right = 0, top = front.height, bottom = 0;
  for (int y = 0; y < front.height; ++y) {
    for (int x = 0; x < front.width; ++x) {
      if (!figure[static_cast<std::size_t>(y) * front.width + x]) continue;
      left = std::min(left, x), right = std::max(right, x), top = std::min(top, y), bottom = std::max(bottom, y);
    }
  }
  // Background inside the door's outline, away from its edges.
  std::size_t through = 0;
  const int margin = (right - left) / 10;
  for (int y = top + margin; y < bottom - margin; ++y) {
    for (int x = left + margin; x < right - margin; ++x) {
      through += figure[static_cast<std::size_t>(y) * front.width + x] ? 0 : 1;
    }
  }
  EXPECT_GT(through, 1000u) << "pixels of the background seen through the windows";
  // The id and depth layers hold nothing there either: the windows' empty
  // texels are no surface.
  for (const char* layer : {"id", "depth"}) {
    const image::Image data = render_ok(client, {{"model", game["id"]}, {"output", layer}});
    ASSERT_EQ(data.width, front.width);
    const Rgb empty = rgb_at(data, 0, 0);
    std::size_t surface = 0;
    for (int y = top + margin; y < bottom - margin; ++y) {
      for (int x = left + margin; x < right - margin; ++x) {
        if (!figure[static_cast<std::size_t>(y) * front.width + x] && rgb_at(data, x, y) != empty) ++surface;
      }
    }
    EXPECT_EQ(surface, 0u) << layer << " layer pixels where the windows show the background";
  }
}

// A desk fan whose B3D names an image ("fan-uv.png") the mod does not ship
// under that name: the mod's one image of it, uploaded beside, is its skin.
TEST_F(GameFiles, AHomedecorDeskFanTakesTheUploadsOneImage) {
  auto client = daemon().client();
  const File skin = file_of("homedecor_desk_fan_uv.png", kExported / "homedecor/homedecor_desk_fan_uv.png");
  const json game =
      upload(client, {file_of("homedecor_desk_fan.b3d", kExported / "homedecor/homedecor_desk_fan.b3d"), skin});
  const json twin = upload(
      client, {file_of("homedecor_desk_fan_twin.glb", kExported / "homedecor/homedecor_desk_fan_twin.glb"), skin});
  EXPECT_TRUE(warns(game, "the upload's one image")) << warnings_of(game);
  EXPECT_EQ(game["textures"], 1);
  expect_like_twin(game["id"], twin["id"], "homedecor_desk_fan");
  expect_like_twin_close_up(game["id"], twin["id"], "homedecor_desk_fan");
}

// OpenArena's red armour: its MD3 names `models/powerups/armor/redArmor`,
// the pack ships `redarmor.tga` (partial alpha on most texels, which Quake
// feeds to shader effects): found, and drawn solid like its opaque twin.
TEST_F(GameFiles, OpenArenasArmorFindsItsTextureAndIsSolid) {
  auto client = daemon().client();
  const File skin = file_of("models/powerups/armor/redarmor.tga", kExported / "openarena/redarmor.tga");
  const json game =
      upload(client, {file_of("models/powerups/armor/armor_red.md3", kExported / "openarena/armor_red.md3"), skin});
  const json twin = upload(
      client, {file_of("models/powerups/armor/armor_red_twin.glb", kExported / "openarena/armor_red_twin.glb"), skin});
  EXPECT_EQ(game["textures"], 1) << warnings_of(game);
  EXPECT_TRUE(warns(game, "found by its name without extension")) << warnings_of(game);
  ASSERT_FALSE(game["material_list"].empty());
  EXPECT_EQ(game["material_list"][0]["alpha"], "opaque");
  expect_like_twin(game["id"], twin["id"], "openarena_armor_red");
}

// Homedecor's calendar, an OBJ with no MTL and its one PNG, is drawn as
// the same OBJ with an MTL naming the PNG.
TEST_F(GameFiles, AnObjWithoutAnMtlTakesTheUploadsOneImage) {
  auto client = daemon().client();
  const std::string obj = read_file(kExported / "homedecor/homedecor_calendar.obj");
  const File png = file_of("homedecor_calendar.png", kExported / "homedecor/homedecor_calendar.png");
  const json bare = upload(client, {{"homedecor_calendar.obj", obj}, png});
  const json with_mtl = upload(client, {{"calendar.obj", "mtllib calendar.mtl\nusemtl paper\n" + obj},
                                        {"calendar.mtl", "newmtl paper\nmap_Kd homedecor_calendar.png\n"},
                                        png});
  EXPECT_EQ(bare["textures"], 1) << warnings_of(bare);
  EXPECT_EQ(bare["material_list"][0]["alpha"], with_mtl["material_list"][0]["alpha"]);
  expect_like_twin(bare["id"], with_mtl["id"], "homedecor_calendar");
}

// 3d_armor's character with the images the mod sets with no armour worn:
// the player's skin on the body, the empty image on the armour and the
// wielded item; an image no material uses is named in the warnings.
TEST_F(GameFiles, ThreeDArmorsCharacterTakesTheModsImagesInMaterialOrder) {
  auto client = daemon().client();
  const std::vector<File> files = {file_of("3d_armor_character.b3d", kExported / "3d_armor/3d_armor_character.b3d"),
                                   file_of("character.png", kExported / "minetest/character.png"),
                                   file_of("3d_armor_trans.png", kExported / "3d_armor/3d_armor_trans.png")};
  const json game = upload(client, files, "?textures=character.png,3d_armor_trans.png,3d_armor_trans.png");
  ASSERT_EQ(game["material_list"].size(), 3u) << game.dump();
  EXPECT_EQ(game["material_list"][0]["texture"], "character.png");
  EXPECT_EQ(game["material_list"][1]["texture"], "3d_armor_trans.png");
  EXPECT_EQ(game["material_list"][2]["texture"], "3d_armor_trans.png");
  const json twin = upload(
      client,
      {file_of("3d_armor_character_twin.glb", kExported / "3d_armor/3d_armor_character_twin.glb"), files[1], files[2]});
  expect_like_twin(game["id"], twin["id"], "3d_armor_character");

  std::vector<File> more = files;
  more.push_back(file_of("spare.png", kExported / "minetest/doors_door_wood.png"));
  const json extra = upload(client, more, "?textures=character.png,3d_armor_trans.png,3d_armor_trans.png");
  EXPECT_TRUE(warns(extra, "no material uses the image 'spare.png'")) << warnings_of(extra);
  // By material name, the same.
  const json named = upload(client, files,
                            "?textures=Character:character.png,Armor:3d_armor_trans.png,"
                            "Wielditem:3d_armor_trans.png");
  EXPECT_EQ(named["material_list"], game["material_list"]);
}

// What `?textures` may not say: an image not in the upload, more images
// than materials, a material the model lacks.
TEST_F(GameFiles, ATexturesListThatDoesNotFitIsRefusedNamingTheField) {
  auto client = daemon().client();
  const std::vector<File> files = {file_of("character.b3d", kExported / "minetest/character.b3d"),
                                   file_of("character.png", kExported / "minetest/character.png")};
  for (const std::string query : {"?textures=nothere.png", "?textures=character.png,character.png",
                                  "?textures=Hat:character.png", "?textures=,,"}) {
    httplib::MultipartFormDataItems items;
    for (const auto& [path, bytes] : files) items.push_back({"file", bytes, path, "application/octet-stream"});
    auto res = client.Post("/models" + query, items);
    ASSERT_TRUE(res);
    EXPECT_GE(res->status, 400) << query;
    EXPECT_LT(res->status, 500) << query;
    EXPECT_EQ(error_of(res)["path"], "?textures") << query << ": " << res->body;
  }
}

// A request draws one material another way: its alpha and its image.
TEST_F(GameFiles, ARequestSetsAMaterialsAlphaAndImage) {
  auto client = daemon().client();
  const json game = minetest_player(client);
  const json twin_files = upload(client,
                                 {file_of("character.b3d", kExported / "minetest/character.b3d"),
                                  file_of("character.png", kExported / "minetest/character.png"),
                                  file_of("other.png", kExported / "minetest/doors_door_wood.png")},
                                 "?textures=character.png");
  const image::Image masked = render_ok(client, {{"model", game["id"]}});
  const image::Image opaque =
      render_ok(client, {{"model", game["id"]}, {"materials", {{"Character", {{"alpha", "opaque"}}}}}});
  EXPECT_GT(figure_differing(masked, opaque, 24.0), 0.02) << "the hat layer's empty texels drawn";
  const image::Image swapped =
      render_ok(client, {{"model", twin_files["id"]}, {"materials", {{"Character", {{"texture", "other.png"}}}}}});
  EXPECT_GT(figure_differing(masked, swapped, 24.0), 0.2);
  auto res = post_json(client, "/render", {{"model", game["id"]}, {"materials", {{"Hat", {{"alpha", "mask"}}}}}});
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 422) << res->body;
  EXPECT_EQ(error_of(res)["path"], "/materials/Hat");
  res = post_json(client, "/render", {{"model", game["id"]}, {"materials", {{"Character", {{"texture", "no.png"}}}}}});
  ASSERT_TRUE(res);
  EXPECT_EQ(error_of(res)["path"], "/materials/Character/texture") << res->body;
}

// The player's twin with NEAREST magnification and one with LINEAR differ
// close up (a sampler was ignored); `textures.filter` chooses for a file
// that says nothing.
TEST_F(GameFiles, AGltfSamplersMagnificationFilterIsHonoured) {
  auto client = daemon().client();
  const std::string nearest = read_file(kExported / "minetest/character_twin.glb");
  const auto chunks = glb::glb_chunks(nearest);
  ASSERT_TRUE(chunks);
  json doc = json::parse(chunks->json);
  doc["samplers"][0]["magFilter"] = 9729;
  const std::string linear = glb::glb_container(doc.dump(), chunks->bin);
  const File png = file_of("character.png", kExported / "minetest/character.png");
  const json a = upload(client, {{"character_twin.glb", nearest}, png});
  const json b = upload(client, {{"character_twin.glb", linear}, png});
  const double close = 0.8 * framing_distance(client, a["id"]);
  const image::Image sharp = render_ok(client, {{"model", a["id"]}, {"camera", {{"distance", close}}}});
  const image::Image soft = render_ok(client, {{"model", b["id"]}, {"camera", {{"distance", close}}}});
  keep(soft, "minetest_player_twin_linear_close");
  const double share = image_differing(sharp, soft, 8.0);
  std::printf("NEAREST against LINEAR close up: %.2f %% of the image differs by > 8 levels\n", 100.0 * share);
  EXPECT_GT(share, 0.01);
  // The B3D says nothing: auto is nearest for its 64x32 skin, linear asked for is the LINEAR twin.
  const json game = minetest_player(client);
  const image::Image asked = render_ok(
      client, {{"model", game["id"]}, {"camera", {{"distance", close}}}, {"textures", {{"filter", "linear"}}}});
  EXPECT_LE(image_differing(asked, soft, 8.0), 0.01);
}

// An MTL's `d 0.5`: the red square is drawn half over the background
// behind it (in linear light, as the sRGB target blends), after the opaque
// surfaces, and in flat shading its colour is exactly that mix.
TEST_F(GameFiles, AnMtlsDissolveBlendsOverWhatIsBehind) {
  auto client = daemon().client();
  const std::string quad = "mtllib q.mtl\nusemtl glass\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n";
  const json glass = upload(client, {{"q.obj", quad}, {"q.mtl", "newmtl glass\nKd 1 0 0\nd 0.5\n"}});
  ASSERT_EQ(glass["material_list"][0]["alpha"], "blend");
  const json request = {{"model", glass["id"]},
                        {"width", 64},
                        {"height", 64},
                        {"shading", {{"mode", "flat"}}},
                        {"outline", {{"enabled", false}}}};
  const image::Image img = render_ok(client, request);
  const auto linear = [](double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); };
  const auto srgb = [](double c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055; };
  const Rgb background = rgb_at(img, 0, 0);
  const Rgb centre = rgb_at(img, 32, 32);
  const double expected_r = 255.0 * srgb(0.5 * linear(background.r / 255.0) + 0.5);
  const double expected_g = 255.0 * srgb(0.5 * linear(background.g / 255.0));
  EXPECT_NEAR(centre.r, expected_r, 3.0);
  EXPECT_NEAR(centre.g, expected_g, 3.0);
  // Opaque on request: red.
  json opaque = request;
  opaque["materials"] = {{"glass", {{"alpha", "opaque"}}}};
  const Rgb solid = rgb_at(render_ok(client, opaque), 32, 32);
  EXPECT_GE(solid.r, 250);
  EXPECT_LE(solid.g, 5);
}

// A two-colour image, as PNG bytes: left half red, right half blue.
std::string two_colour_png() {
  image::Image img;
  img.width = img.height = 64;
  for (int y = 0; y < 64; ++y) {
    for (int x = 0; x < 64; ++x) {
      if (x < 32) {
        img.rgba.insert(img.rgba.end(), {220, 30, 30, 255});
      } else {
        img.rgba.insert(img.rgba.end(), {30, 30, 220, 255});
      }
    }
  }
  return image::encode_png(img);
}

// Cube 2's flag: an .md5mesh and its .md5anim beside it give a clip that
// moves, and the upload's one image is drawn.
TEST_F(GameFiles, AnMd5MeshTakesTheClipOfItsMd5AnimAndItsImage) {
  auto client = daemon().client();
  const json flag = upload(client, {file_of("ffflag.md5mesh", kExported / "cube2/ffflag/ffflag.md5mesh"),
                                    file_of("ffflag.md5anim", kExported / "cube2/ffflag/ffflag.md5anim"),
                                    {"ffflag_cc.png", two_colour_png()}});
  ASSERT_TRUE(flag.contains("animation")) << flag.dump();
  ASSERT_EQ(flag["animation"]["clips"].size(), 1u) << flag.dump();
  const double duration = flag["animation"]["clips"][0]["duration"];
  EXPECT_GT(duration, 1.0);
  EXPECT_EQ(flag["textures"], 1) << warnings_of(flag);
  const image::Image start = render_ok(client, {{"model", flag["id"]}, {"animation", {{"clip", 0}, {"time", 0.0}}}});
  const image::Image later =
      render_ok(client, {{"model", flag["id"]}, {"animation", {{"clip", 0}, {"time", duration / 2}}}});
  keep(later, "cube2_ffflag_mid_clip");
  EXPECT_GT(image_differing(start, later, 24.0), 0.01) << "the clip moves the flag";
  std::size_t red = 0;
  std::size_t blue = 0;
  for (int y = 0; y < later.height; ++y) {
    for (int x = 0; x < later.width; ++x) {
      const Rgb c = rgb_at(later, x, y);
      red += c.r > c.b + 60 ? 1 : 0;
      blue += c.b > c.r + 60 ? 1 : 0;
    }
  }
  EXPECT_GT(red, 500u);
  EXPECT_GT(blue, 500u);
}

// Yo Frankie!'s squirrel: its IQM and its run clip's IQM (poses alone) make
// one model with the run clip, its two images on its two meshes by name;
// the clip file uploaded alone is refused in plain words.
TEST_F(GameFiles, FrankiesIqmTakesTheRunClipBesideIt) {
  auto client = daemon().client();
  const fs::path dir = kExported / "cube2/frankie";
  const json frankie =
      upload(client,
             {file_of("Frankie.iqm", dir / "Frankie.iqm"), file_of("Frankie_Run.iqm", dir / "Frankie_Run.iqm"),
              file_of("frankie_tail2.png", dir / "frankie_tail2.png"),
              file_of("flyingsquirrel_skin_col.jpg", dir / "flyingsquirrel_skin_col.jpg")},
             "?textures=Tail:frankie_tail2.png,Body:flyingsquirrel_skin_col.jpg");
  ASSERT_TRUE(frankie.contains("animation")) << frankie.dump();
  const json& clips = frankie["animation"]["clips"];
  ASSERT_EQ(clips.size(), 1u) << frankie.dump();
  EXPECT_EQ(clips[0]["name"], "Frankie_Run");
  EXPECT_EQ(frankie["textures"], 2) << warnings_of(frankie);
  const double duration = clips[0]["duration"];
  const image::Image a = render_ok(client, {{"model", frankie["id"]}, {"animation", {{"clip", 0}, {"time", 0.0}}}});
  const image::Image b =
      render_ok(client, {{"model", frankie["id"]}, {"animation", {{"clip", 0}, {"time", duration / 2}}}});
  keep(a, "cube2_frankie_run_start");
  keep(b, "cube2_frankie_run_middle");
  EXPECT_GT(image_differing(a, b, 24.0), 0.01) << "the run moves the squirrel";

  httplib::MultipartFormDataItems alone = {
      {"file", read_file(dir / "Frankie_Run.iqm"), "Frankie_Run.iqm", "application/octet-stream"}};
  auto res = client.Post("/models", alone);
  ASSERT_TRUE(res);
  EXPECT_EQ(res->status, 422) << res->body;
  const std::string message = error_of(res)["message"];
  EXPECT_NE(message.find("holds only 1 clip ('Frankie_Run')"), std::string::npos) << message;
  EXPECT_NE(message.find("upload it together with the model it animates"), std::string::npos) << message;
  EXPECT_EQ(message.find("aiScene"), std::string::npos) << message;
}

// Snout's IQM names its author's PNGs by absolute path; the JPEGs shipped
// beside it are found by name.
TEST_F(GameFiles, SnoutsJpegsAreFoundFromThePngPathsItsFileNames) {
  auto client = daemon().client();
  const fs::path dir = kExported / "cube2/snoutx10k";
  const json snout = upload(client, {file_of("snoutx10k.iqm", dir / "snoutx10k.iqm"),
                                     file_of("lower.jpg", dir / "lower.jpg"), file_of("upper.jpg", dir / "upper.jpg")});
  EXPECT_EQ(snout["textures"], 2) << warnings_of(snout);
  EXPECT_TRUE(warns(snout, "was found by its name without extension, as 'lower.jpg'")) << warnings_of(snout);
  EXPECT_TRUE(warns(snout, "as 'upper.jpg'")) << warnings_of(snout);
  keep(render_ok(client, {{"model", snout["id"]}}), "cube2_snoutx10k");
}

}  // namespace
}  // namespace toond::test
