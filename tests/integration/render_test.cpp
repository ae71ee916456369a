// What the image shows: size, coverage, bands, texture, outline ring.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "image/png_codec.h"
#include "support/generated_models.h"
#include "support/image_checks.h"
#include "support/shared_models.h"
#include "test_client.h"

namespace toond::test {
namespace {

using nlohmann::json;

class Render : public SharedDaemonTest {
 protected:
  std::string upload(const std::string& folder) {
    auto client = daemon().client();
    auto res = upload_model_folder(client, shared_models_dir() / folder);
    if (!res || (res->status != 200 && res->status != 201)) {
      ADD_FAILURE() << "upload of " << folder << " failed: " << (res ? res->body : "no answer");
      return {};
    }
    return json::parse(res->body)["id"];
  }
};

TEST_F(Render, DemoModelRendersAtTheRequestedSize) {
  auto client = daemon().client();
  const auto img = render_ok(client, {{"width", 320}, {"height", 200}});
  EXPECT_EQ(img.width, 320);
  EXPECT_EQ(img.height, 200);
  const double cover = coverage(foreground_mask(img));
  EXPECT_GT(cover, 0.15);
  EXPECT_LT(cover, 0.85);
}

// With one sample a pixel the wireframe's line coverage cannot pick
// samples: it is blended over the image, which stays as opaque as its
// background (it once wrote the coverage into the image's alpha).
TEST_F(Render, AWireframeWithoutMultisamplingLeavesTheImageOpaque) {
  auto client = daemon().client();
  for (int msaa : {1, 4}) {
    const json request = {
        {"width", 160}, {"height", 128}, {"msaa", msaa}, {"outline", {{"method", "wireframe"}, {"width", 2.5}}}};
    const auto img = render_ok(client, request);
    json unlined = request;
    unlined["outline"]["enabled"] = false;
    EXPECT_GT(differing_share(img, render_ok(client, unlined), 3), 0.01)
        << "msaa " << msaa << ": the wireframe is drawn";
    std::size_t translucent = 0;
    for (std::size_t i = 3; i < img.rgba.size(); i += 4) translucent += img.rgba[i] != 255;
    EXPECT_EQ(translucent, 0u) << "msaa " << msaa;
  }
}

TEST_F(Render, DefaultsGiveA512SquareImage) {
  auto client = daemon().client();
  const auto img = render_ok(client, json::object());
  EXPECT_EQ(img.width, 512);
  EXPECT_EQ(img.height, 512);
}

TEST_F(Render, BackgroundColourIsHonoured) {
  auto client = daemon().client();
  const auto img = render_ok(client, {{"width", 64}, {"height", 64}, {"background", {1, 0, 0, 1}}});
  const Rgb corner = rgb_at(img, 0, 0);
  EXPECT_EQ(corner, (Rgb{255, 0, 0}));
}

// Front light, front camera, no antialiasing: every visible point has
// N·L > 0, so a model with one colour shows exactly `steps` flat colours.
TEST_F(Render, BandCountEqualsSteps) {
  TOOND_REQUIRE_SHARED_MODELS();
  const std::string id = upload("stanford-bunny");
  auto client = daemon().client();
  for (int steps : {2, 3, 5}) {
    const json params = {{"model", id},
                         {"msaa", 1},
                         {"camera", {{"yaw", 0}, {"pitch", 0}}},
                         {"lights", {{{"type", "directional"}, {"direction", {0, 0, -1}}}}},
                         {"outline", {{"enabled", false}}},
                         {"specular", {{"enabled", false}}},
                         {"shading", {{"steps", steps}, {"band_aa", false}}}};
    const auto img = render_ok(client, params);
    const auto mask = foreground_mask(img);
    ASSERT_GT(coverage(mask), 0.1);
    // Without antialiasing every pixel is a band colour; grazing pixels at
    // the silhouette may show the unlit level (N·L <= 0) too.
    EXPECT_LE(colour_histogram(img, mask).size(), static_cast<std::size_t>(steps) + 1);
    EXPECT_EQ(dominant_colours(img, mask, 0.002), static_cast<std::size_t>(steps)) << "steps " << steps;
  }
}

TEST_F(Render, PhongIsSmoothWhereCelIsBanded) {
  TOOND_REQUIRE_SHARED_MODELS();
  const std::string id = upload("stanford-bunny");
  auto client = daemon().client();
  json params = {{"model", id}, {"msaa", 1}, {"outline", {{"enabled", false}}}};
  params["shading"] = {{"mode", "phong"}};
  const auto phong = render_ok(client, params);
  // Hard bands: with band antialiasing the edges hold blends too.
  params["shading"] = {{"mode", "cel"}, {"steps", 3}, {"band_aa", false}};
  const auto cel = render_ok(client, params);
  const auto phong_colours = colour_histogram(phong, foreground_mask(phong)).size();
  const auto cel_colours = colour_histogram(cel, foreground_mask(cel)).size();
  EXPECT_GT(phong_colours, 4 * cel_colours) << "phong " << phong_colours << " cel " << cel_colours;
}

// Spot's texture has black patches; without the texture the cow is one
// colour and nothing inside it is that dark.
TEST_F(Render, SpotShowsItsTexture) {
  TOOND_REQUIRE_SHARED_MODELS();
  auto client = daemon().client();
  const auto folder = shared_models_dir() / "spot";
  auto with = upload_files(client, folder, {"spot.obj", "spot.mtl", "spot_texture.png"});
  auto without = upload_files(client, folder, {"spot.obj", "spot.mtl"});
  ASSERT_TRUE(with && without);
  auto dark_fraction = [&](const std::string& id) {
    const auto img = render_ok(client, {{"model", id}, {"outline", {{"enabled", false}}}, {"msaa", 1}});
    const auto mask = foreground_mask(img);
    std::size_t dark = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x)
        if (mask[static_cast<std::size_t>(y) * img.width + x] && luminance(rgb_at(img, x, y)) < 0.25) ++dark;
    return static_cast<double>(dark) / static_cast<double>(count(mask));
  };
  const double textured = dark_fraction(json::parse(with->body)["id"]);
  const double plain = dark_fraction(json::parse(without->body)["id"]);
  EXPECT_GT(textured, 0.03) << "black patches of the texture";
  EXPECT_LT(plain, 0.001);
}

// Two objects, two materials, each with its own diffuse texture: leaving out
// either texture changes a good part of the image, so both are drawn.
TEST_F(Render, MultiMaterialModelShowsEveryMaterialsTexture) {
  TOOND_REQUIRE_SHARED_MODELS();
  auto client = daemon().client();
  const auto folder = shared_models_dir() / "windmill";
  const std::vector<std::string> all = {"windmill.obj", "windmill.mtl", "windmill_001_base_COL.jpg",
                                        "windmill_001_lopatky_COL.jpg"};
  auto render_without = [&](const std::string& left_out) {
    std::vector<std::string> files;
    for (const auto& f : all)
      if (f != left_out) files.push_back(f);
    auto res = upload_files(client, folder, files);
    EXPECT_TRUE(res && (res->status == 200 || res->status == 201));
    const std::string id = json::parse(res->body)["id"];
    return render_ok(client, {{"model", id}, {"msaa", 1}, {"outline", {{"enabled", false}}}});
  };
  const auto full = render_without("");
  EXPECT_GT(coverage(foreground_mask(full)), 0.05);
  for (const char* texture : {"windmill_001_base_COL.jpg", "windmill_001_lopatky_COL.jpg"}) {
    const auto partial = render_without(texture);
    std::size_t changed = 0;
    for (int y = 0; y < full.height; ++y)
      for (int x = 0; x < full.width; ++x) changed += rgb_at(full, x, y) != rgb_at(partial, x, y) ? 1 : 0;
    EXPECT_GT(static_cast<double>(changed) / (full.width * full.height), 0.01) << "without " << texture;
  }
}

// The windmill's map_Bump files are tangent-space normal maps: with them the
// thresholded lighting of the same geometry changes over much of the model.
TEST_F(Render, NormalMapsChangeTheShading) {
  TOOND_REQUIRE_SHARED_MODELS();
  auto client = daemon().client();
  const auto folder = shared_models_dir() / "windmill";
  auto render_with = [&](const std::vector<std::string>& files) {
    auto res = upload_files(client, folder, files);
    EXPECT_TRUE(res && (res->status == 200 || res->status == 201));
    const json info = json::parse(res->body);
    const std::string id = info["id"];
    auto rendered = post_json(client, "/render",
                              {{"model", id},
                               {"msaa", 1},
                               {"outline", {{"enabled", false}}},
                               {"specular", {{"enabled", false}}},
                               {"shading", {{"base", "white"}}}});
    EXPECT_TRUE(rendered && rendered->status == 200);
    return image::decode_png(rendered->body);
  };
  const std::vector<std::string> base = {"windmill.obj", "windmill.mtl"};
  std::vector<std::string> with_maps = base;
  with_maps.insert(with_maps.end(), {"windmill_001_base_NOR.jpg", "windmill_001_lopatky_NOR.jpg"});
  const auto flat = render_with(base);
  const auto bumpy = render_with(with_maps);
  // Same geometry, same light: only the normal maps can change the shading.
  const auto mask = foreground_mask(flat);
  std::size_t model = 0, changed = 0;
  for (int y = 0; y < flat.height; ++y)
    for (int x = 0; x < flat.width; ++x) {
      if (!mask[static_cast<std::size_t>(y) * flat.width + x]) continue;
      ++model;
      changed += rgb_at(flat, x, y) != rgb_at(bumpy, x, y) ? 1 : 0;
    }
  EXPECT_GT(static_cast<double>(changed) / static_cast<double>(model), 0.05) << changed << " of " << model;
}

// OBJ vertex colours (v x y z r g b) are the base colour: in flat mode each
// face shows exactly the colour its vertices give.
TEST_F(Render, VertexColoursAreTheBaseColour) {
  auto client = daemon().client();
  const std::string quad =
      "v -1 -1 0 1 0 0\nv 1 -1 0 1 0 0\nv 1 1 0 1 0 0\nv -1 1 0 1 0 0\n"
      "v -1 -1 -1 0 0 1\nv 1 -1 -1 0 0 1\nv 1 1 -1 0 0 1\nv -1 1 -1 0 0 1\n"
      "f 1 2 3 4\nf 5 6 7 8\n";
  const std::string id = upload_obj_text(client, quad, "coloured.obj");
  const auto img = render_ok(client, {{"model", id},
                                      {"msaa", 1},
                                      {"shading", {{"mode", "flat"}}},
                                      {"camera", {{"yaw", 0}, {"pitch", 0}}},
                                      {"outline", {{"enabled", false}}}});
  EXPECT_EQ(rgb_at(img, img.width / 2, img.height / 2), (Rgb{255, 0, 0})) << "the front quad is red";
}

// The hull outline is the difference between a render with and without
// it: it must lie outside the model, be dark, and close around the
// silhouette. (Crease lines, which hard-edged models get inside, are left
// out here: Effects tests them.)
void expect_closed_dark_ring(httplib::Client& client, json params, double width) {
  params["msaa"] = 1;
  params["outline"] = {{"enabled", false}};
  const auto bare = render_ok(client, params);
  params["outline"] = {{"enabled", true}, {"width", width}, {"color", {0, 0, 0}}, {"creases", "never"}};
  const auto outlined = render_ok(client, params);
  ASSERT_EQ(bare.width, outlined.width);
  const int w = bare.width, h = bare.height;
  const auto model = foreground_mask(bare);
  std::vector<bool> ring(model.size());
  std::size_t ring_pixels = 0, inside_changes = 0, light_ring = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      if (rgb_at(bare, x, y) == rgb_at(outlined, x, y)) continue;
      if (model[i]) {
        ++inside_changes;
        continue;
      }
      ring[i] = true;
      ++ring_pixels;
      if (luminance(rgb_at(outlined, x, y)) > 0.1) ++light_ring;
    }
  }
  EXPECT_EQ(inside_changes, 0u) << "the stencil keeps the outline off the model";
  EXPECT_GT(ring_pixels, 0u);
  EXPECT_EQ(light_ring, 0u) << "every outline pixel is dark";
  // Closed: each silhouette pixel touches the ring within one pixel.
  const auto edge = boundary(model, w, h);
  std::size_t open = 0;
  for (int y = 1; y < h - 1; ++y) {
    for (int x = 1; x < w - 1; ++x) {
      if (!edge[static_cast<std::size_t>(y) * w + x]) continue;
      bool touches = false;
      for (int dy = -1; dy <= 1 && !touches; ++dy)
        for (int dx = -1; dx <= 1 && !touches; ++dx) touches = ring[static_cast<std::size_t>(y + dy) * w + x + dx];
      // Silhouette pixels whose neighbours are all model pixels or ring pixels
      // only; a background neighbour with no ring is a gap.
      bool background_neighbour = false;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const std::size_t j = static_cast<std::size_t>(y + dy) * w + x + dx;
          background_neighbour |= !model[j] && !ring[j];
        }
      if (!touches || background_neighbour) ++open;
    }
  }
  EXPECT_EQ(open, 0u) << "silhouette pixels with background and no outline next to them";
}

TEST_F(Render, OutlineIsAClosedDarkRingAroundSpot) {
  TOOND_REQUIRE_SHARED_MODELS();
  const std::string id = upload("spot");
  auto client = daemon().client();
  expect_closed_dark_ring(client, {{"model", id}}, 3);
}

// Hard edges split vertices; extruding along the shading normals would
// tear the hull open at every corner of this blocky dog.
TEST_F(Render, OutlineStaysClosedOnAHardEdgedModel) {
  TOOND_REQUIRE_SHARED_MODELS();
  const std::string id = upload("kenney-cube-pet-dog");
  auto client = daemon().client();
  expect_closed_dark_ring(client, {{"model", id}, {"camera", {{"yaw", 35}, {"pitch", 25}}}}, 4);
}

// Texture mode: the line takes the inverted, darkened texture under it, so
// a textured model's outline has many colours where the fixed mode has one.
TEST_F(Render, OutlineColourFromTheTexture) {
  TOOND_REQUIRE_SHARED_MODELS();
  const std::string id = upload("spot");
  auto client = daemon().client();
  json params = {{"model", id}, {"msaa", 1}, {"outline", {{"enabled", false}}}};
  const auto bare = render_ok(client, params);
  auto ring = [&](const std::string& mode) {
    params["outline"] = {{"enabled", true}, {"width", 4}, {"color_mode", mode}, {"darken", 0.3}};
    const auto img = render_ok(client, params);
    std::map<Rgb, std::size_t> colours;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x)
        if (rgb_at(bare, x, y) != rgb_at(img, x, y)) ++colours[rgb_at(img, x, y)];
    return colours;
  };
  EXPECT_EQ(ring("fixed").size(), 1u);
  const auto textured = ring("texture");
  EXPECT_GT(textured.size(), 20u);
  // Spot is mostly white: inverted and darkened, most of its outline is dark.
  std::size_t dark = 0, total = 0;
  for (const auto& [c, n] : textured) {
    total += n;
    dark += luminance(c) < 0.5 ? n : 0;
  }
  EXPECT_GT(dark, total / 2);
}

TEST_F(Render, OutlineOnTheDemoModel) {
  auto client = daemon().client();
  expect_closed_dark_ring(client, json::object(), 2);
}

// Width in pixels does not depend on how far away the camera is, and is the
// width asked for: on a smooth sphere the outermost ring pixel lies `width`
// pixels from the nearest model pixel (pixel centres), within a pixel.
TEST_F(Render, OutlineWidthIsInPixelsAtAnyDistance) {
  auto client = daemon().client();
  const std::string sphere = upload_obj_text(client, sphere_obj(96, 48), "sphere.obj");
  auto measured_width = [&](double distance, double width) {
    json params = {{"model", sphere}, {"msaa", 1}, {"camera", {{"fov", 30}, {"distance", distance}}}};
    params["outline"] = {{"enabled", false}};
    const auto bare = render_ok(client, params);
    params["outline"] = {{"enabled", true}, {"width", width}};
    return outline_width_px(bare, render_ok(client, params));
  };
  for (double width : {2.0, 5.0, 9.0}) {
    const double near_width = measured_width(4.5, width);  // the sphere fills the frame
    const double far_width = measured_width(12.0, width);  // about a third of that
    EXPECT_NEAR(near_width, width, 0.75) << "width " << width;
    EXPECT_NEAR(far_width, width, 0.75) << "width " << width;
    EXPECT_NEAR(near_width, far_width, 0.5) << "width " << width;
  }
}

// On hard edges the hull moves every face plane out by the width (a mitre),
// so the ring is never thinner than asked; where an edge is seen corner-on
// it can be up to sqrt(2) times wider, never gapped.
TEST_F(Render, HardEdgeOutlineIsAtLeastTheWidth) {
  auto client = daemon().client();
  const std::string cube = upload_obj_text(client, cube_obj(), "cube.obj");
  for (double yaw : {0.0, 30.0, 45.0}) {
    json params = {{"model", cube}, {"msaa", 1}, {"camera", {{"yaw", yaw}, {"pitch", 20}}}};
    params["outline"] = {{"enabled", false}};
    const auto bare = render_ok(client, params);
    params["outline"] = {{"enabled", true}, {"width", 6}};
    const double width = outline_width_px(bare, render_ok(client, params));
    EXPECT_GE(width, 6.0 - 0.75) << "yaw " << yaw;
    EXPECT_LE(width, 6.0 * std::sqrt(2.0) + 0.75) << "yaw " << yaw;
  }
}

TEST_F(Render, OutlineStaysClosedOnAGeneratedCube) {
  auto client = daemon().client();
  const std::string cube = upload_obj_text(client, cube_obj(), "cube.obj");
  for (double yaw : {0.0, 30.0, 45.0}) {
    expect_closed_dark_ring(client, {{"model", cube}, {"camera", {{"yaw", yaw}, {"pitch", 20}}}}, 3);
  }
}

// Supersampling keeps the output size and the look, and smooths edges:
// without any antialiasing a silhouette pixel is model or background; with
// 3× supersampling many edge pixels are in-between blends.
TEST_F(Render, SupersamplingSmoothsEdgesAtTheSameSize) {
  auto client = daemon().client();
  const std::string sphere = upload_obj_text(client, sphere_obj(64, 32), "sphere.obj");
  json params = {{"model", sphere},
                 {"width", 128},
                 {"height", 96},
                 {"msaa", 1},
                 {"outline", {{"enabled", false}}},
                 {"specular", {{"enabled", false}}}};
  const auto sharp = render_ok(client, params);
  params["supersample"] = 3;
  auto res = post_json(client, "/render", params);
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200) << res->body;
  EXPECT_NE(res->get_header_value("X-Toond-Passes").find("downsample"), std::string::npos);
  const auto smooth = image::decode_png(res->body);
  ASSERT_EQ(smooth.width, 128);
  ASSERT_EQ(smooth.height, 96);
  const auto sharp_colours = colour_histogram(sharp, foreground_mask(sharp)).size();
  const auto smooth_colours = colour_histogram(smooth, foreground_mask(smooth)).size();
  EXPECT_GT(smooth_colours, sharp_colours + 20) << sharp_colours << " vs " << smooth_colours;
  // Same look: the two images agree on most pixels.
  std::size_t same = 0;
  for (int y = 0; y < 96; ++y)
    for (int x = 0; x < 128; ++x) same += rgb_at(sharp, x, y) == rgb_at(smooth, x, y) ? 1 : 0;
  EXPECT_GT(static_cast<double>(same) / (128 * 96), 0.85);
}

TEST_F(Render, OneShotMultipartRenderUploadsAndRenders) {
  TOOND_REQUIRE_SHARED_MODELS();
  auto client = daemon().client();
  const auto folder = shared_models_dir() / "spot";
  httplib::MultipartFormDataItems items;
  for (const char* f : {"spot.obj", "spot.mtl", "spot_texture.png"}) {
    items.push_back({"file", read_file(folder / f), f, "application/octet-stream"});
  }
  items.push_back({"params", json{{"width", 200}, {"height", 100}}.dump(), "", "application/json"});
  auto res = client.Post("/render", items);
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200) << res->body;
  const auto img = image::decode_png(res->body);
  EXPECT_EQ(img.width, 200);
  EXPECT_EQ(img.height, 100);
  EXPECT_GT(coverage(foreground_mask(img)), 0.05);
}

TEST_F(Render, ServerTimingNamesThePassesThatRan) {
  auto client = daemon().client();
  auto res = post_json(client, "/render", {{"width", 64}, {"height", 64}, {"outline", {{"width", 0}}}, {"msaa", 1}});
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200);
  EXPECT_EQ(res->get_header_value("X-Toond-Passes"), "main,readback");
  EXPECT_NE(res->get_header_value("Server-Timing").find("main;dur="), std::string::npos);
  auto with_outline = post_json(client, "/render", {{"width", 64}, {"height", 64}, {"msaa", 4}});
  ASSERT_TRUE(with_outline);
  // The demo model's box is hard-edged: its crease lines join the outline.
  EXPECT_EQ(with_outline->get_header_value("X-Toond-Passes"), "main,hull_outline,creases,resolve,readback");
}

// `total` is the request's own work; the passes' thread times and the
// encoding fit inside it.
TEST_F(Render, ServerTimingEndsWithTheTotal) {
  auto client = daemon().client();
  auto res = post_json(client, "/render", {{"width", 64}, {"height", 64}, {"camera", {{"yaw", 17}}}});
  ASSERT_TRUE(res);
  ASSERT_EQ(res->status, 200);
  const std::string timing = res->get_header_value("Server-Timing");
  const auto total_at = timing.find("total;dur=");
  ASSERT_NE(total_at, std::string::npos) << timing;
  const double total = std::stod(timing.substr(total_at + 10));
  const auto png_at = timing.find("png;dur=");
  ASSERT_NE(png_at, std::string::npos) << timing;
  EXPECT_GE(total, std::stod(timing.substr(png_at + 8))) << timing;
  EXPECT_GT(total, 0.0);
}

// GL guarantees at least 4 samples; more are clamped to what the driver has,
// a count it has no mode for gets the next one up (llvmpipe: 2 gives 4),
// and the answer says what was used.
TEST_F(Render, SamplesHeaderSaysWhatMsaaReallyUsed) {
  auto client = daemon().client();
  auto samples = [&](int msaa) {
    auto res = post_json(client, "/render", {{"width", 32}, {"height", 32}, {"msaa", msaa}});
    EXPECT_TRUE(res && res->status == 200);
    return res ? std::stoi(res->get_header_value("X-Toond-Samples", 0)) : -1;
  };
  EXPECT_EQ(samples(1), 1);
  EXPECT_EQ(samples(4), 4);
  const int two = samples(2);
  EXPECT_GE(two, 2);
  EXPECT_LE(two, 4);
  auto health = client.Get("/healthz");
  ASSERT_TRUE(health);
  if (nlohmann::json::parse(health->body).at("gl").at("renderer").get<std::string>().find("llvmpipe") !=
      std::string::npos) {
    EXPECT_EQ(two, 4) << "llvmpipe has 1 and 4 samples per pixel only";
  }
  const int eight = samples(8);
  EXPECT_GE(eight, 4);
  EXPECT_LE(eight, 8);
}

}  // namespace
}  // namespace toond::test
