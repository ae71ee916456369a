// The `output` layers over HTTP: lines that composite back to the full
// render, depth along the view axis, view-space normals and ids per object
// or material; each read by Python's PIL, not by our own decoder (which
// reduces 16-bit samples to 8).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <set>

#include "image/png_codec.h"
#include "image/srgb.h"
#include "support/generated_models.h"
#include "support/golden_compare.h"
#include "support/image_checks.h"
#include "support/shared_models.h"
#include "test_client.h"

namespace toond::test {
namespace {

using nlohmann::json;

// What PIL decodes: the image's size, mode and tEXt chunks, and its
// samples (16-bit grey as integers; palette images as their indices when
// `indices`, else made RGBA like everything else: a lines or normal layer
// of few colours is written with a palette too).
struct PilImage {
  int width = 0;
  int height = 0;
  std::string mode;
  json text;
  std::vector<int> samples;  // one per pixel (grey, index) or four (RGBA)
  int at(int x, int y, int channel = 0) const {
    const int per_pixel = static_cast<int>(samples.size() / (static_cast<std::size_t>(width) * height));
    return samples[(static_cast<std::size_t>(y) * width + x) * per_pixel + channel];
  }
};

bool pil_available() { return run_process({"/usr/bin/python3", "-c", "import PIL"}).status == 0; }

PilImage decode_with_pil(const std::string& png, bool indices = false) {
  const auto dir = make_temp_dir("toond-layer");
  std::ofstream(dir / "layer.png", std::ios::binary) << png;
  const auto r = run_process({"/usr/bin/python3", "-c",
                              "import sys, json\n"
                              "from PIL import Image\n"
                              "im = Image.open(sys.argv[1]); im.load()\n"
                              "mode = im.mode\n"
                              "raw = ('P', 'I', 'I;16', 'L') if sys.argv[2] == 'indices' else ('I', 'I;16', 'L')\n"
                              "data = list(im.getdata()) if mode in raw else\\\n"
                              "  [c for p in im.convert('RGBA').getdata() for c in p]\n"
                              "print(json.dumps({'size': list(im.size), 'mode': mode,"
                              " 'text': dict(im.text), 'samples': data}))\n",
                              (dir / "layer.png").string(), indices ? "indices" : "rgba"});
  EXPECT_EQ(r.status, 0) << r.err;
  if (r.status != 0) return {};
  const json seen = json::parse(r.out);
  return {seen["size"][0], seen["size"][1], seen["mode"], seen["text"], seen["samples"].get<std::vector<int>>()};
}

class OutputLayers : public SharedDaemonTest {
 public:
  static httplib::Client daemon_client() { return daemon().client(); }

 protected:
  static httplib::Result post(const json& params) {
    auto client = daemon().client();
    return post_json(client, "/render", params);
  }
  static std::string png_of(const json& params) {
    auto res = post(params);
    if (!res || res->status != 200) {
      ADD_FAILURE() << params.dump() << " answered "
                    << (res ? std::to_string(res->status) + ": " + res->body : "nothing");
      return {};
    }
    EXPECT_EQ(res->get_header_value("Content-Type"), "image/png");
    return res->body;
  }
  // A unit sphere alone, seen straight on, orthographic, 96²: its centre
  // is the image's centre.
  static json sphere_params(const std::string& output) {
    static const std::string sphere = [] {
      auto client = daemon().client();
      return upload_obj_text(client, sphere_obj(64, 32), "sphere.obj");
    }();
    return {{"model", sphere},
            {"width", 96},
            {"height", 96},
            {"output", output},
            {"camera", {{"projection", "orthographic"}, {"yaw", 0}, {"pitch", 0}}}};
  }
};

// Lines composited in linear light over `colour`: what the renderer does
// when it draws them into the colour itself.
image::Image composite_over(const image::Image& lines, const image::Image& colour) {
  const auto& to_linear = image::srgb_to_linear_table();
  image::Image out = colour;
  for (std::size_t i = 0; i < out.rgba.size(); i += 4) {
    const float a = lines.rgba[i + 3] / 255.0f;
    for (int c = 0; c < 3; ++c) {
      const float v = to_linear[lines.rgba[i + c]] * a + to_linear[colour.rgba[i + c]] * (1.0f - a);
      out.rgba[i + c] = image::linear_to_srgb_byte(v);
    }
  }
  return out;
}

// The three renders of one look: the full colour, the colour without any
// line, and the lines layer.
struct LineRenders {
  image::Image full, bare, lines;
};

LineRenders render_lines_and_colour(const json& look) {
  auto client = OutputLayers::daemon_client();
  json full = look;
  full["width"] = 160;
  full["height"] = 128;
  json bare = full;
  bare["outline"]["enabled"] = false;
  bare["contour"]["enabled"] = false;
  json lines = full;
  lines["output"] = "lines";
  return {render_ok(client, full), render_ok(client, bare), render_ok(client, lines)};
}

// The layer holds the lines and nothing else: most of it is clear, and
// at least 1 % of it (every look draws more than a silhouette of lines)
// is not.
void expect_lines_alone(const image::Image& lines, const json& look) {
  std::size_t clear = 0;
  for (std::size_t i = 3; i < lines.rgba.size(); i += 4) clear += lines.rgba[i] == 0;
  const std::size_t pixels = lines.rgba.size() / 4;
  EXPECT_GT(clear, pixels * 3 / 4) << look.dump();
  EXPECT_GT(pixels - clear, pixels / 100) << look.dump();
}

// Every kind of line: hull, wireframe and screen-space edges, crease lines
// on the demo's box, both contour styles, and a floor that hides what lies
// under it; the default dark lines and coloured ones (whose partly covered
// pixels only come back right if the layer's colour is divided by its
// alpha).
const json kLineLooks[] = {
    json::object(),
    {{"outline", {{"method", {"hull", "wireframe", "edges"}}, {"width", 2.5}, {"color", {0.95, 0.45, 0.1}}}},
     {"contour", {{"enabled", true}, {"style", "fresnel"}, {"color", {0.2, 0.5, 0.95}}}},
     {"floor", {{"enabled", true}}}},
    {{"outline", {{"method", "edges"}, {"color", {0.1, 0.8, 0.3}}}}, {"contour", {{"enabled", true}}}},
};

// One sample a pixel, every pixel the lines cover in part is covered by
// the edge pass's own blend, which is an "over" in linear light: composited
// over the colour without lines, the layer gives the full render back.
TEST_F(OutputLayers, WithoutAntialiasingLinesOverTheBareColourGiveTheFullRender) {
  for (json look : kLineLooks) {
    look["msaa"] = 1;
    const LineRenders r = render_lines_and_colour(look);
    EXPECT_GT(differing_share(r.full, r.bare, 3), 0.01) << look.dump() << ": the lines change the colour render";
    const GoldenDiff diff = compare_golden(r.full, composite_over(r.lines, r.bare));
    EXPECT_TRUE(diff.passes()) << look.dump() << ": " << diff.pixels_over << " pixels differ by more than "
                               << kGoldenLevels << " levels, largest " << diff.largest;
    expect_lines_alone(r.lines, look);
  }
}

// Antialiased (the default request, and supersampling), a pixel's
// coverage says how much of it a line covers but not which samples: where
// a hull line meets the model's silhouette it hides background samples
// only, and an "over" of its coverage hides a share of the model too. In
// linear light the error is then the covered share A times the difference
// between the hidden samples and the pixel's average, at most min(A, 1-A);
// fully covered and uncovered pixels are exact.
TEST_F(OutputLayers, AntialiasedLinesOverTheBareColourDifferOnlyByTheSamplesTheyHide) {
  const auto& to_linear = image::srgb_to_linear_table();
  std::vector<json> looks(std::begin(kLineLooks), std::end(kLineLooks));
  looks.push_back({{"contour", {{"enabled", true}, {"color", {0.9, 0.2, 0.6}}}}, {"supersample", 2}, {"msaa", 1}});
  for (const json& look : looks) {
    const LineRenders r = render_lines_and_colour(look);
    const image::Image composed = composite_over(r.lines, r.bare);
    std::size_t partial = 0, over_golden = 0, over_bound = 0;
    double worst_excess = 0;
    for (std::size_t i = 0; i < composed.rgba.size(); i += 4) {
      const float a = r.lines.rgba[i + 3] / 255.0f;
      partial += a > 0.0f && a < 1.0f;
      // One level of rounding in each of the three 8-bit images.
      const float bound = std::min(a, 1.0f - a) + 3.0f / 255.0f;
      bool golden_ok = true;
      for (int c = 0; c < 3; ++c) {
        const float error = std::abs(to_linear[composed.rgba[i + c]] - to_linear[r.full.rgba[i + c]]);
        worst_excess = std::max(worst_excess, static_cast<double>(error - bound));
        if (error > bound) ++over_bound;
        golden_ok = golden_ok && std::abs(composed.rgba[i + c] - r.full.rgba[i + c]) <= kGoldenLevels;
      }
      over_golden += !golden_ok;
    }
    std::printf("[lines] %s: %zu partly covered pixels, %zu off by more than %d levels\n", look.dump().c_str(), partial,
                over_golden, kGoldenLevels);
    EXPECT_GT(partial, 20u) << look.dump() << ": antialiased lines have partly covered pixels";
    EXPECT_EQ(over_bound, 0u) << look.dump() << ": worst excess " << worst_excess;
    // The edges method blends its lines by coverage in the colour render
    // too, so its "over" hides nothing it should not: exact to the golden
    // tolerance (only the contour's own samples may differ).
    const bool blended_lines = look.contains("outline") && look["outline"].value("method", json()) == "edges";
    if (blended_lines) {
      EXPECT_LE(over_golden, kGoldenPixels) << look.dump();
    }
    expect_lines_alone(r.lines, look);
  }
}

TEST_F(OutputLayers, DepthGrowsAlongARayIntoTheSphereAndNamesItsRange) {
  if (!pil_available()) GTEST_SKIP() << "/usr/bin/python3 with PIL is absent (Debian: python3-pil)";
  auto res = post(sphere_params("depth"));
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200) << res->body;
  const PilImage depth = decode_with_pil(res->body);
  ASSERT_EQ(depth.width, 96);
  EXPECT_TRUE(depth.mode == "I;16" || depth.mode == "I") << depth.mode;
  // From the centre (nearest) out to the silhouette the surface recedes:
  // every step right is no nearer, and the last covered pixel is far.
  const int y = 48;
  int last = -1;
  int x = 48;
  for (; x < 96 && depth.at(x, y) != 65535; ++x) {
    EXPECT_GE(depth.at(x, y), last) << "at x " << x;
    last = depth.at(x, y);
  }
  EXPECT_LT(depth.at(48, y), 200) << "the centre is near the nearest depth";
  EXPECT_GT(last, 40000) << "the silhouette is near the farthest";
  EXPECT_LT(x, 96) << "the background is 65535";
  EXPECT_EQ(depth.at(0, 0), 65535);

  const json range = json::parse(depth.text["toond:depth"].get<std::string>());
  const double span = range["far"].get<double>() - range["near"].get<double>();
  // Orthographic, straight on: from the sphere's front to its silhouette is
  // its radius, to within the pixel the silhouette sample lands in.
  EXPECT_NEAR(span, 1.0, 0.06);
  const std::string header = res->get_header_value("X-Toond-Depth-Range");
  EXPECT_NE(header.find("near="), std::string::npos) << header;
  EXPECT_NE(header.find("far="), std::string::npos) << header;
}

TEST_F(OutputLayers, TheNormalAtTheSpheresCentreFacesTheViewer) {
  if (!pil_available()) GTEST_SKIP() << "/usr/bin/python3 with PIL is absent (Debian: python3-pil)";
  const PilImage normal = decode_with_pil(png_of(sphere_params("normal")));
  ASSERT_EQ(normal.width, 96);
  // The four pixels round the centre: (0.5, 0.5, 1.0) within 1/255, past
  // the half pixel they lie off it.
  for (int y : {47, 48}) {
    for (int x : {47, 48}) {
      EXPECT_NEAR(normal.at(x, y, 0), 127.5, 2.5) << x << "," << y;
      EXPECT_NEAR(normal.at(x, y, 1), 127.5, 2.5) << x << "," << y;
      EXPECT_GE(normal.at(x, y, 2), 254) << x << "," << y;
      EXPECT_EQ(normal.at(x, y, 3), 255);
    }
  }
  // x right, y up: right of the centre the normal turns right, above it up.
  EXPECT_GT(normal.at(80, 48, 0), 200);
  EXPECT_GT(normal.at(48, 16, 1), 200);
  EXPECT_LT(normal.at(16, 48, 0), 55) << "left of the centre it turns left";
  EXPECT_LT(normal.at(48, 80, 1), 55) << "below it, down";
  EXPECT_EQ(normal.at(0, 0, 3), 0) << "the background is transparent";
}

TEST_F(OutputLayers, ATwoObjectSceneNumbersItsObjects) {
  if (!pil_available()) GTEST_SKIP() << "/usr/bin/python3 with PIL is absent (Debian: python3-pil)";
  auto client = daemon().client();
  const std::string sphere = upload_obj_text(client, sphere_obj(32, 16), "ball.obj");
  const std::string cube = upload_obj_text(client, cube_obj(0.8), "box.obj");
  const json params = {{"width", 128},
                       {"height", 64},
                       {"output", "id"},
                       {"camera", {{"yaw", 0}, {"pitch", 0}}},
                       {"objects",
                        {{{"model", sphere}, {"transform", {{"translate", {-1.5, 0, 0}}}}},
                         {{"model", cube}, {"transform", {{"translate", {1.5, 0, 0}}}}}}}};
  const PilImage ids = decode_with_pil(png_of(params), true);
  ASSERT_EQ(ids.width, 128);
  EXPECT_EQ(ids.mode, "P");
  EXPECT_EQ(std::set<int>(ids.samples.begin(), ids.samples.end()), (std::set<int>{0, 1, 2}));
  EXPECT_EQ(ids.at(32, 32), 1) << "the first object, on the left";
  EXPECT_EQ(ids.at(96, 32), 2) << "the second, on the right";
  EXPECT_EQ(ids.at(64, 2), 0) << "the background";
  const json mapping = json::parse(ids.text["toond:ids"].get<std::string>());
  EXPECT_EQ(mapping["by"], "object");
  ASSERT_EQ(mapping["ids"].size(), 2u);
  EXPECT_EQ(mapping["ids"][0]["model"], sphere);
  EXPECT_EQ(mapping["ids"][1]["model"], cube);
}

TEST_F(OutputLayers, ALoneModelIsNumberedByMaterial) {
  if (!pil_available()) GTEST_SKIP() << "/usr/bin/python3 with PIL is absent (Debian: python3-pil)";
  // The demo model: a ball of one material on a base of another.
  const PilImage ids = decode_with_pil(png_of({{"width", 96}, {"height", 96}, {"output", "id"}}), true);
  EXPECT_EQ(std::set<int>(ids.samples.begin(), ids.samples.end()), (std::set<int>{0, 1, 2}));
  const json mapping = json::parse(ids.text["toond:ids"].get<std::string>());
  EXPECT_EQ(mapping["by"], "material");
  ASSERT_EQ(mapping["ids"].size(), 2u);
  // Each id where its material is: the ball ("body") above, the base below.
  auto material_at = [&](int x, int y) {
    for (const json& entry : mapping["ids"]) {
      if (entry["id"] == ids.at(x, y)) return entry["material"].get<std::string>();
    }
    return std::string("(no id)");
  };
  EXPECT_EQ(material_at(48, 40), "body");
  EXPECT_EQ(material_at(48, 76), "base");
  EXPECT_EQ(ids.at(2, 2), 0) << "the background";
}

TEST_F(OutputLayers, EachLayerWorksWithASheet) {
  if (!pil_available()) GTEST_SKIP() << "/usr/bin/python3 with PIL is absent (Debian: python3-pil)";
  for (const char* output : {"lines", "depth", "normal", "id"}) {
    const json params = {{"width", 48}, {"height", 40}, {"output", output}, {"sheet", {{"frames", 4}, {"columns", 2}}}};
    const PilImage sheet = decode_with_pil(png_of(params), std::string(output) == "id");
    ASSERT_EQ(sheet.width, 96) << output;
    ASSERT_EQ(sheet.height, 80) << output;
    EXPECT_TRUE(sheet.text.contains("toond:atlas")) << output;
    // Every tile shows the model: its centre pixel is not background; the
    // lines layer has lines in every tile and is clear in its corners.
    const std::string kind = output;
    for (int tile = 0; tile < 4; ++tile) {
      const int x0 = (tile % 2) * 48;
      const int y0 = (tile / 2) * 40;
      if (kind == "lines") {
        int lines = 0;
        for (int y = y0; y < y0 + 40; ++y) {
          for (int x = x0; x < x0 + 48; ++x) lines += sheet.at(x, y, 3) > 0;
        }
        EXPECT_GT(lines, 40) << "tile " << tile;
        EXPECT_EQ(sheet.at(x0, y0, 3), 0) << "tile " << tile;
        continue;
      }
      const int cx = x0 + 24;
      const int cy = y0 + 20;
      const bool shown = kind == "depth" ? sheet.at(cx, cy) < 65535
                         : kind == "id"  ? sheet.at(cx, cy) > 0
                                         : sheet.at(cx, cy, 3) > 0;
      EXPECT_TRUE(shown) << output << " tile " << tile;
    }
  }
  // One depth range over the whole sheet: the nearest pixel of all frames
  // is 0 and the farthest 65534, and the frames do not each span the whole
  // range, as a range per frame would make them (the demo's square box
  // turned by 45° reaches nearer and farther than face on; turned by 90°
  // it would look the same).
  const PilImage depth = decode_with_pil(png_of({{"width", 48},
                                                 {"height", 40},
                                                 {"output", "depth"},
                                                 {"sheet", {{"frames", 4}, {"columns", 2}, {"yaw_step", 45}}}}));
  int nearest = 65535, farthest = -1, tiles_spanning_all = 0;
  for (int tile = 0; tile < 4; ++tile) {
    int tile_near = 65535, tile_far = -1;
    for (int y = (tile / 2) * 40; y < (tile / 2) * 40 + 40; ++y) {
      for (int x = (tile % 2) * 48; x < (tile % 2) * 48 + 48; ++x) {
        const int v = depth.at(x, y);
        if (v == 65535) continue;
        tile_near = std::min(tile_near, v);
        tile_far = std::max(tile_far, v);
      }
    }
    nearest = std::min(nearest, tile_near);
    farthest = std::max(farthest, tile_far);
    tiles_spanning_all += tile_near == 0 && tile_far == 65534;
  }
  EXPECT_EQ(nearest, 0);
  EXPECT_EQ(farthest, 65534);
  EXPECT_LT(tiles_spanning_all, 4) << "each frame was scaled to its own range";
}

TEST_F(OutputLayers, TheDataLayersRunNoShadingAndNoOutline) {
  for (const char* output : {"depth", "normal", "id"}) {
    auto res = post({{"width", 32},
                     {"height", 32},
                     {"output", output},
                     {"shadows", {{"enabled", true}}},
                     {"floor", {{"enabled", true}}}});
    ASSERT_TRUE(res);
    ASSERT_EQ(res->status, 200) << res->body;
    EXPECT_EQ(res->get_header_value("X-Toond-Passes"), "layer,readback") << output;
    EXPECT_EQ(res->get_header_value("X-Toond-Samples"), "1") << output;
  }
}

TEST_F(OutputLayers, TheCliAsksForALayerWithOutput) {
  const auto png = make_temp_dir("toon-layer") / "lines.png";
  const auto r = run_process({TOON_BINARY, "render", "--output", "lines", "--set", "width=48", "--set", "height=48",
                              "-o", png.string(), "--server", daemon().url()});
  ASSERT_EQ(r.status, 0) << r.err;
  const image::Image lines = image::decode_png(read_file(png));
  EXPECT_EQ(lines.pixel(0, 0)[3], 0) << "the lines layer is clear where there is no line";
  const auto bad =
      run_process({TOON_BINARY, "render", "--output", "albedo", "-o", png.string(), "--server", daemon().url()});
  EXPECT_NE(bad.status, 0);
  EXPECT_NE(bad.err.find("output"), std::string::npos) << bad.err;
}

TEST_F(OutputLayers, BadOutputsAreRefused) {
  auto unknown = post({{"width", 32}, {"height", 32}, {"output", "albedo"}});
  ASSERT_TRUE(unknown);
  EXPECT_EQ(unknown->status, 400) << unknown->body;
  EXPECT_EQ(error_of(unknown)["path"], "/output");

  // 256 materials, one triangle each: one more than an id layer's indices.
  std::string mtl, obj = "mtllib many.mtl\n";
  for (int m = 0; m < 256; ++m) {
    mtl += "newmtl m" + std::to_string(m) + "\nKd 0.5 0.5 0.5\n";
    const double x = m % 16, y = m / 16.0;
    obj += "v " + std::to_string(x) + " " + std::to_string(y) + " 0\nv " + std::to_string(x + 0.9) + " " +
           std::to_string(y) + " 0\nv " + std::to_string(x) + " " + std::to_string(y + 0.9) + " 0\n";
    obj += "usemtl m" + std::to_string(m) + "\nf -3 -2 -1\n";
  }
  const auto dir = make_temp_dir("toond-many-materials");
  std::ofstream(dir / "many.obj") << obj;
  std::ofstream(dir / "many.mtl") << mtl;
  auto client = daemon().client();
  auto uploaded = upload_files(client, dir, {"many.obj", "many.mtl"});
  ASSERT_TRUE(uploaded);
  ASSERT_EQ(uploaded->status / 100, 2) << uploaded->body;
  const std::string id = json::parse(uploaded->body)["id"];
  auto too_many = post({{"model", id}, {"width", 32}, {"height", 32}, {"output", "id"}});
  ASSERT_TRUE(too_many);
  EXPECT_EQ(too_many->status, 422) << too_many->body;
  EXPECT_EQ(error_of(too_many)["code"], "too_many_ids");
  EXPECT_EQ(error_of(too_many)["path"], "/output");
  auto colour = post({{"model", id}, {"width", 32}, {"height", 32}});
  ASSERT_TRUE(colour);
  EXPECT_EQ(colour->status, 200) << "the same model renders in colour";
}

}  // namespace
}  // namespace toond::test
