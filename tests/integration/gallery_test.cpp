// `toon gallery` against a real daemon: one small shared model, every look,
// the folder of PNGs, the contact sheet and the index page; the glTF model
// toon writes from an OBJ; and a model the daemon refuses, which fails the
// run but not the files.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "image/png_codec.h"
#include "support/image_checks.h"
#include "support/shared_models.h"
#include "test_client.h"

namespace toond::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

class Gallery : public SharedDaemonTest {
 protected:
  ProcessResult toon(std::vector<std::string> args) {
    args.insert(args.begin(), TOON_BINARY);
    args.push_back("--server");
    args.push_back(daemon().url());
    return run_process(args);
  }

  // The look count the run announces: "rendering 28 looks (10 presets, 18 effects) ...".
  static void announced_looks(const std::string& err, int& looks, int& presets) {
    std::smatch m;
    ASSERT_TRUE(std::regex_search(err, m, std::regex(R"(rendering (\d+) looks \((\d+) presets, (\d+) effects\))")))
        << err;
    looks = std::stoi(m[1]);
    presets = std::stoi(m[2]);
    EXPECT_EQ(looks, presets + std::stoi(m[3]));
  }

  std::size_t preset_count() {
    auto client = daemon().client();
    auto res = client.Get("/presets");
    EXPECT_TRUE(res);
    if (!res) return 0;
    return json::parse(res->body).size();
  }

  static std::vector<fs::path> pngs_in(const fs::path& dir) {
    std::vector<fs::path> out;
    for (const auto& e : fs::directory_iterator(dir)) {
      if (e.path().extension() == ".png") out.push_back(e.path());
    }
    std::sort(out.begin(), out.end());
    return out;
  }
};

TEST_F(Gallery, OneSharedModelEveryLookASheetAndAPage) {
  TOOND_REQUIRE_SHARED_MODELS();
  const fs::path out = make_temp_dir("toon-gallery") / "out";
  const std::string model = "kenney-space-craft";
  const auto r = toon(
      {"gallery", "--models", shared_models_dir().string() + "/", "--only", model, "--size", "64", "-o", out.string()});
  ASSERT_EQ(r.status, 0) << r.err;

  int looks = 0, presets = 0;
  announced_looks(r.err, looks, presets);
  EXPECT_EQ(static_cast<std::size_t>(presets), preset_count());
  EXPECT_GE(looks - presets, 15);
  // Progress: one line per render, the last "[N/N] model/look".
  EXPECT_NE(r.err.find("[1/" + std::to_string(looks) + "] " + model + "/"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("[" + std::to_string(looks) + "/" + std::to_string(looks) + "] " + model + "/sprite_sheet"),
            std::string::npos)
      << r.err;

  // One PNG per look, each a 64×64 render but the sprite sheet's 4 × 2
  // tiles of 64×64.
  const auto pngs = pngs_in(out / model);
  ASSERT_EQ(pngs.size(), static_cast<std::size_t>(looks));
  std::set<std::string> names;
  for (const fs::path& png : pngs) {
    names.insert(png.stem().string());
    const auto img = image::decode_png(read_file(png));
    const bool sheet = png.stem() == "sprite_sheet";
    EXPECT_EQ(img.width, sheet ? 4 * 64 : 64) << png;
    EXPECT_EQ(img.height, sheet ? 2 * 64 : 64) << png;
  }
  for (const char* look : {"bw_comic", "noir", "default", "halftone_dots", "shadows_floor", "msaa_8", "point_light",
                           "lines_layer", "sprite_sheet"}) {
    EXPECT_TRUE(names.count(look)) << look;
  }
  // The lines layer is the lines alone: its corner is clear.
  EXPECT_EQ(image::decode_png(read_file(out / model / "lines_layer.png")).pixel(0, 0)[3], 0);

  // The contact sheet: one row of 64-pixel thumbnails with 2-pixel gaps and border.
  const auto sheet = image::decode_png(read_file(out / "contact-sheet.png"));
  EXPECT_EQ(sheet.width, looks * 64 + (looks + 1) * 2);
  EXPECT_EQ(sheet.height, 64 + 2 * 2);
  // The first thumbnail is the first preset's render, unchanged at factor 1.
  const auto first = image::decode_png(read_file(out / model / "lines_only.png"));
  for (int y : {0, 31, 63}) {
    for (int x : {0, 20, 40, 63}) {
      const std::uint8_t* a = first.pixel(x, y);
      const std::uint8_t* b = sheet.pixel(2 + x, 2 + y);
      EXPECT_EQ(std::vector<int>(a, a + 3), std::vector<int>(b, b + 3)) << x << "," << y;
    }
  }

  // The page shows every image, with its parameters and a toon render command.
  const std::string html = read_file(out / "index.html");
  EXPECT_NE(html.find("src=\"contact-sheet.png\""), std::string::npos);
  for (const fs::path& png : pngs) {
    const std::string rel = model + "/" + png.filename().string();
    EXPECT_NE(html.find("src=\"" + rel + "\""), std::string::npos) << rel;
    EXPECT_NE(html.find("-o " + png.filename().string()), std::string::npos) << rel;
  }
  // --models DIR/ with its slash: the command names the OBJ as DIR/model/file.obj.
  EXPECT_NE(html.find("toon render " + (shared_models_dir() / model / "craft_speederA.obj").string() + " "),
            std::string::npos);
  EXPECT_NE(html.find("&quot;preset&quot;: &quot;bw_comic&quot;"), std::string::npos);
  EXPECT_EQ(html.find("class=\"failed\""), std::string::npos);
}

// The gallery's glTF model: bob's OBJ written by toon as a .glb, kept
// beside its renders, uploaded as glTF, and every look drawn as the OBJ's.
TEST_F(Gallery, BobAsGlbRendersEveryLookLikeItsObj) {
  TOOND_REQUIRE_SHARED_MODELS();
  const fs::path out = make_temp_dir("toon-gallery-glb") / "out";
  const auto r = toon({"gallery", "--models", shared_models_dir().string(), "--only", "bob.glb,bob", "--size", "64",
                       "-o", out.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("uploading bob.glb: 1 file"), std::string::npos) << r.err;

  const fs::path glb = out / "bob.glb" / "bob_tri.glb";
  ASSERT_TRUE(fs::is_regular_file(glb));
  EXPECT_EQ(read_file(glb).substr(0, 4), "glTF");

  int looks = 0, presets = 0;
  announced_looks(r.err, looks, presets);
  const auto from_glb = pngs_in(out / "bob.glb");
  ASSERT_EQ(from_glb.size(), static_cast<std::size_t>(looks));
  for (const fs::path& png : from_glb) {
    const auto glb_image = image::decode_png(read_file(png));
    const auto obj_image = image::decode_png(read_file(out / "bob" / png.filename()));
    // Stray pixels at most, as for the tests' own twins (GltfRender); the
    // .glb has no Ks, but bob's faint green one changes no pixel by 24.
    EXPECT_LT(differing_share(glb_image, obj_image, 24), 0.005) << png.filename();
  }

  // The page's commands render the .glb that was uploaded.
  const std::string html = read_file(out / "index.html");
  EXPECT_NE(html.find("toon render " + glb.generic_string() + " "), std::string::npos);
}

TEST_F(Gallery, ARefusedModelFailsTheRunButTheRestIsWritten) {
  const fs::path root = make_temp_dir("toon-gallery-models");
  fs::create_directories(root / "points");
  fs::create_directories(root / "triangle");
  fs::create_directories(root / "empty-folder");
  std::ofstream(root / "points" / "p.obj") << "v 0 0 0\nv 1 0 0\n";
  std::ofstream(root / "triangle" / "t.obj") << "v -1 0 0\nv 1 0 0\nv 0 1.5 0\nf 1 2 3\n";
  const fs::path out = root / "out";

  const auto r = toon({"gallery", "--models", root.string(), "--all", "--size", "32", "-o", out.string()});
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("skipping empty-folder"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("points: upload failed"), std::string::npos) << r.err;
  int looks = 0, presets = 0;
  announced_looks(r.err, looks, presets);
  EXPECT_NE(r.err.find(std::to_string(looks) + " of " + std::to_string(2 * looks) + " renders failed"),
            std::string::npos)
      << r.err;

  EXPECT_EQ(pngs_in(out / "triangle").size(), static_cast<std::size_t>(looks));
  EXPECT_FALSE(fs::exists(out / "points" / "default.png"));
  const auto sheet = image::decode_png(read_file(out / "contact-sheet.png"));
  EXPECT_EQ(sheet.width, looks * 32 + (looks + 1) * 2);
  EXPECT_EQ(sheet.height, 2 * 32 + 3 * 2);
  const std::string html = read_file(out / "index.html");
  EXPECT_NE(html.find("triangle/default.png"), std::string::npos);
  EXPECT_NE(html.find("no faces"), std::string::npos) << "the daemon's reason is on the page";
  EXPECT_NE(html.find(std::to_string(looks) + " failed"), std::string::npos);
}

TEST_F(Gallery, UsageErrorsComeBeforeAnyRequest) {
  const fs::path root = make_temp_dir("toon-gallery-usage");
  auto r = toon({"gallery", "--models", (root / "absent").string(), "-o", (root / "out").string()});
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("not a folder"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(root / "out"));
  r = toon({"gallery", "--models", root.string()});
  EXPECT_EQ(r.status, 2) << r.err;
}

}  // namespace
}  // namespace toond::test
