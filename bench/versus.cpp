#include "versus.h"

#include <chrono>
#include <cstdio>
#include <iostream>

#include "bench_http.h"
#include "floor_ratios.h"
#include "gpu/egl_context.h"
#include "gpu/render_target.h"
#include "image/png_codec.h"
#include "image_error.h"
#include "stats.h"
#include "throughput.h"

namespace toond::bench {
namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// What the server cannot avoid for one answer: clear the target, resolve
// and read it back, encode the PNG. Measured here on a context of our own.
json floor_of(const image::Image& content, int samples, int png_level, int repeats) {
  gpu::EglContext context(gpu::EglContext::Options{});
  gpu::RenderTarget target(content.width, content.height, samples);
  std::vector<double> readback, encode;
  for (int i = 0; i < repeats + 1; ++i) {
    auto t0 = Clock::now();
    target.bind_for_drawing();
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    const image::Image back = target.read_back();
    const double r = ms_since(t0);
    t0 = Clock::now();
    const std::string png = image::encode_png(content, {png_level});
    const double e = ms_since(t0);
    if (i == 0 || back.rgba.empty() || png.empty()) continue;  // the first one allocates
    readback.push_back(r);
    encode.push_back(e);
  }
  return {{"clear_readback_ms", median(readback)},
          {"png_encode_ms", median(encode)},
          {"total_ms", median(readback) + median(encode)}};
}

}  // namespace

// What drawing the same mesh costs at the least: the same request (size,
// samples, level of detail) with one constant colour and nothing else (no
// lights, bands, outline or effects), read back and encoded as usual. A
// frame's time over this says what the toon look itself costs.
json geometry_floor_of(httplib::Client& client, const json& request, int repeats) {
  const json params = geometry_floor_request(request);
  render_timed(client, params);  // warm
  std::vector<double> server, png;
  TimedRender last;
  for (int i = 0; i < repeats; ++i) {
    last = render_timed(client, params);
    server.push_back(last.server_ms);
    png.push_back(last.png_ms);
  }
  return {{"server_ms", median(server)}, {"png_ms", median(png)}, {"lod_drawn", last.lod}};
}

json run_versus(httplib::Client& client, const std::string& url, const std::filesystem::path& models, int repeats,
                double load_seconds) {
  std::cerr << "bench: toond side of the three.js comparison (bunny 512²)\n";
  const std::string bunny = upload_folder(client, models / "stanford-bunny");
  const json base = {{"model", bunny},
                     {"width", 512},
                     {"height", 512},
                     {"shading", {{"steps", 3}}},
                     {"specular", {{"enabled", false}}},
                     {"outline", {{"enabled", true}, {"width", 1.5}}}};
  json configs = json::array();
  for (int msaa : {1, 4}) {
    image::Image full_image;
    for (const char* lod : {"full", "auto"}) {
      json params = base;
      params["msaa"] = msaa;
      params["lod"] = lod;
      // The same without the outline, in turn with it: what no way of
      // drawing the outline could go below.
      json no_outline = params;
      no_outline["outline"] = {{"enabled", false}};
      render_timed(client, params);  // warm
      render_timed(client, no_outline);
      std::vector<double> wall, server, png, wall_no_outline;
      TimedRender last;
      for (int i = 0; i < repeats; ++i) {
        last = render_timed(client, params);
        wall.push_back(last.wall_ms);
        server.push_back(last.server_ms);
        png.push_back(last.png_ms);
        wall_no_outline.push_back(render_timed(client, no_outline).wall_ms);
      }
      const image::Image img = image::decode_png(last.png);
      json c = {{"msaa", msaa},
                {"lod", lod},
                {"lod_drawn", last.lod},
                {"wall_ms", median(wall)},
                {"wall_p90_ms", percentile(wall, 0.9)},
                {"server_ms", median(server)},
                {"png_ms", median(png)},
                {"without_outline_wall_ms", median(wall_no_outline)}};
      if (std::string(lod) == "full") {
        full_image = img;
      } else {
        const PixelError e = compare_images(full_image, img);
        c["pct_pixels_off_vs_full"] = e.pct_off;
        c["mean_abs_error_vs_full"] = e.mean_abs;
      }
      c["floor"] = floor_of(img, msaa, 3, repeats);
      c["server_over_floor"] = c["server_ms"].get<double>() / c["floor"]["total_ms"].get<double>();
      c["geometry_floor"] = geometry_floor_of(client, params, repeats);
      c["server_over_geometry_floor"] = c["server_ms"].get<double>() / c["geometry_floor"]["server_ms"].get<double>();
      std::fprintf(stderr,
                   "  msaa %d lod %-4s: request-to-PNG %7.2f ms (%.2f without the outline), server %7.2f ms (floor "
                   "%.2f ms; geometry floor %.2f ms, ratio %.2f)  [%s]\n",
                   msaa, lod, c["wall_ms"].get<double>(), c["without_outline_wall_ms"].get<double>(),
                   c["server_ms"].get<double>(), c["floor"]["total_ms"].get<double>(),
                   c["geometry_floor"]["server_ms"].get<double>(), c["server_over_geometry_floor"].get<double>(),
                   last.lod.c_str());
      configs.push_back(c);
    }
  }
  json out = {{"model", "stanford-bunny"}, {"size", 512}, {"configs", configs}};
  if (load_seconds > 0) {
    std::cerr << "bench: load, default settings (auto LOD, msaa default)\n";
    json params = base;
    params.erase("specular");
    out["load"] = throughput_json(run_throughput(url, params, {1, 4, 16}, load_seconds));
  }
  return out;
}

}  // namespace toond::bench
