#include "quality_sweep.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <set>

#include "bench_http.h"
#include "image/png_codec.h"
#include "image_error.h"
#include "stats.h"
#include "support/generated_models.h"

namespace toond::bench {
namespace {

using nlohmann::json;

struct Scene {
  std::string name;
  json base;                 // what every point of the scene shares
  bool analytic = false;     // the sphere oracle: band-edge error
  bool shadow_knob = false;  // sweep the shadow map on this scene
  bool png_knob = false;     // sweep the PNG level on this scene
};

// The sphere oracle's scene (see image_error.h): 3 ceil-rounded bands.
constexpr int kSphereSteps = 3;

json sphere_params(const std::string& id, int size) {
  return {{"model", id},
          {"width", size},
          {"height", size},
          {"background", {0, 0, 0}},
          {"camera", {{"projection", "orthographic"}, {"yaw", 0}, {"pitch", 0}}},
          {"lights", {{{"type", "directional"}, {"direction", {0, 0, -1}}, {"color", {1, 1, 1}}, {"intensity", 1}}}},
          {"ambient", 0},
          {"shading", {{"mode", "cel"}, {"steps", kSphereSteps}, {"rounding", "ceil"}, {"base", "white"}}},
          {"specular", {{"enabled", false}}},
          {"outline", {{"enabled", false}}}};
}

// The knob values a point renders with, completed from the schema defaults.
json effective(const json& defaults, const json& patch) {
  json s = defaults;
  for (const char* key : {"msaa", "supersample", "lod", "lod_error_px", "png_compression"}) {
    if (patch.contains(key)) s[key] = patch[key];
  }
  if (patch.contains("shadows") && patch["shadows"].contains("map_size")) s["map_size"] = patch["shadows"]["map_size"];
  return s;
}

json schema_defaults(httplib::Client& client) {
  auto res = client.Get("/schema");
  if (!res || res->status != 200) throw std::runtime_error("GET /schema failed");
  const json schema = json::parse(res->body);
  const json& p = schema.at("properties");
  return {{"msaa", p.at("msaa").at("default")},
          {"supersample", p.at("supersample").at("default")},
          {"lod", p.at("lod").at("default")},
          {"lod_error_px", p.at("lod_error_px").at("default")},
          {"png_compression", p.at("png_compression").at("default")},
          {"map_size", p.at("shadows").at("properties").at("map_size").at("default")}};
}

struct Knob {
  std::string family;
  std::string label;
  json patch;
};

std::vector<Knob> knobs_for(const Scene& scene, const SweepOptions& o) {
  std::vector<Knob> knobs;
  if (o.smoke) return {{"msaa×ss", "msaa 1 ss 1", {{"msaa", 1}, {"supersample", 1}}}};
  const std::vector<int> msaa = o.quick ? std::vector<int>{1, 4, 8} : std::vector<int>{1, 2, 4, 8};
  const std::vector<int> ss = o.quick ? std::vector<int>{1, 2} : std::vector<int>{1, 2, 3, 4};
  for (int s : ss)
    for (int m : msaa)
      knobs.push_back(
          {"msaa×ss", "msaa " + std::to_string(m) + " ss " + std::to_string(s), {{"msaa", m}, {"supersample", s}}});
  knobs.push_back({"lod", "lod full", {{"lod", "full"}}});
  const std::vector<double> budgets =
      o.quick ? std::vector<double>{0.5, 2} : std::vector<double>{0.125, 0.25, 0.5, 1, 2, 4};
  for (double b : budgets) {
    char label[32];
    std::snprintf(label, sizeof label, "lod %g px", b);
    knobs.push_back({"lod", label, {{"lod", "auto"}, {"lod_error_px", b}}});
  }
  if (scene.shadow_knob) {
    const std::vector<int> maps = o.quick ? std::vector<int>{512, 2048} : std::vector<int>{512, 1024, 2048, 4096};
    for (int m : maps) knobs.push_back({"shadow map", "map " + std::to_string(m), {{"shadows", {{"map_size", m}}}}});
  }
  if (scene.png_knob) {
    const std::vector<int> levels = o.quick ? std::vector<int>{1, 3, 9} : std::vector<int>{0, 1, 2, 3, 6, 9};
    for (int l : levels) knobs.push_back({"png", "png " + std::to_string(l), {{"png_compression", l}}});
  }
  return knobs;
}

struct Measured {
  std::vector<double> wall, server, png;
  TimedRender last;
};

// Times every point of a scene in rounds: each round renders each point
// once untimed (its target, shadow map and programs ready again) and then
// its share of the repeats. Slow drift of the machine (turbo, a neighbour)
// then falls on every point alike, instead of on whichever points came
// last; settings that draw the very same image were measured 2 ms apart
// when timed one after the other.
std::vector<Measured> measure_in_rounds(httplib::Client& client, const std::vector<json>& params, int repeats) {
  std::vector<Measured> measured(params.size());
  const int rounds = std::min(repeats, 3);
  for (int round = 0; round < rounds; ++round) {
    const int share = repeats / rounds + (round < repeats % rounds ? 1 : 0);
    for (std::size_t i = 0; i < params.size(); ++i) {
      Measured& m = measured[i];
      render_timed(client, params[i]);  // warm
      for (int k = 0; k < share; ++k) {
        m.last = render_timed(client, params[i]);
        m.wall.push_back(m.last.wall_ms);
        m.server.push_back(m.last.server_ms);
        m.png.push_back(m.last.png_ms);
      }
    }
  }
  return measured;
}

std::vector<Scene> make_scenes(httplib::Client& client, const SweepOptions& o) {
  std::vector<Scene> scenes;
  const int sphere_size = o.smoke ? 64 : 512;
  const std::string sphere = upload_obj(client, test::sphere_obj(192, 96), "sphere.obj");
  scenes.push_back({"sphere (analytic)", sphere_params(sphere, sphere_size), true, false, false});
  if (o.smoke || o.models.empty() || !std::filesystem::is_directory(o.models)) return scenes;
  const std::string spot = upload_folder(client, o.models / "spot");
  const std::string bunny = upload_folder(client, o.models / "stanford-bunny");
  const std::string windmill = upload_folder(client, o.models / "windmill");
  scenes.push_back({"spot", {{"model", spot}}, false, false, false});
  scenes.push_back({"bunny", {{"model", bunny}}, false, false, true});
  scenes.push_back({"windmill (2 materials, 5 textures)", {{"model", windmill}}, false, false, false});
  // A sun from above-left throws spot's shadow onto the floor.
  scenes.push_back({"spot + floor + shadows",
                    {{"model", spot},
                     {"camera", {{"yaw", 30}, {"pitch", 25}}},
                     {"lights", {{{"type", "directional"}, {"direction", {-0.5, -1, -0.4}}}}},
                     {"shadows", {{"enabled", true}}},
                     {"floor", {{"enabled", true}}}},
                    false,
                    true,
                    false});
  return scenes;
}

}  // namespace

SweepResult run_quality_sweep(httplib::Client& client, const SweepOptions& o) {
  SweepResult result;
  result.defaults = schema_defaults(client);
  const std::vector<Scene> scenes = make_scenes(client, o);
  const int repeats = o.smoke ? 1 : o.repeats;
  for (const Scene& scene : scenes) {
    std::cerr << "bench: " << scene.name << "\n";
    // The reference: everything at its finest.
    json ref_params = scene.base;
    ref_params.merge_patch({{"msaa", 8}, {"supersample", o.smoke ? 2 : 4}, {"lod", "full"}});
    if (scene.shadow_knob) ref_params.merge_patch({{"shadows", {{"map_size", 4096}}}});
    const TimedRender ref = render_timed(client, ref_params);
    const image::Image reference = image::decode_png(ref.png);
    image::Image silhouette;
    if (scene.analytic) {
      json flat = ref_params;
      flat["shading"]["mode"] = "flat";
      silhouette = image::decode_png(render_timed(client, flat).png);
    }

    PlotPanel panel;
    panel.title = scene.name;
    panel.error_label = scene.analytic ? "band-edge error, mean px" : "% pixels off the reference";
    std::map<std::string, image::Image> full_detail;  // non-LOD settings → the lod full image
    std::vector<Knob> knobs = knobs_for(scene, o);
    knobs.push_back({"reference", "reference", {{"msaa", 8}, {"supersample", o.smoke ? 2 : 4}, {"lod", "full"}}});
    if (scene.shadow_knob) knobs.back().patch["shadows"] = {{"map_size", 4096}};
    // Each distinct setting once: e.g. "msaa 4 ss 1" is also "lod 0.5 px"
    // at the defaults.
    std::vector<const Knob*> points;
    std::vector<json> point_params;
    std::set<std::string> distinct;
    for (const Knob& knob : knobs) {
      if (!distinct.insert(effective(result.defaults, knob.patch).dump()).second) continue;
      points.push_back(&knob);
      point_params.push_back(scene.base);
      point_params.back().merge_patch(knob.patch);
    }
    const std::vector<Measured> measured = measure_in_rounds(client, point_params, repeats);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const Knob& knob = *points[i];
      const json settings = effective(result.defaults, knob.patch);
      const Measured& m = measured[i];
      const image::Image img = image::decode_png(m.last.png);
      SweepPoint p;
      p.scene = scene.name;
      p.family = knob.family;
      p.label = knob.label;
      p.settings = settings;
      p.lod_header = m.last.lod;
      p.wall_ms = median(m.wall);
      p.server_ms = median(m.server);
      p.server_p25_ms = percentile(m.server, 0.25);
      p.server_p75_ms = percentile(m.server, 0.75);
      p.png_ms = median(m.png);
      p.png_bytes = m.last.png_bytes;
      const PixelError e = compare_images(reference, img);
      p.mean_abs = e.mean_abs;
      p.pct_off = e.pct_off;
      if (scene.analytic) {
        const BandEdgeError b = sphere_band_edge_error(silhouette, img, kSphereSteps);
        p.band_edge_px = b.mean_px;
        p.band_edge_max_px = b.max_px;
      }
      // LOD points also against full detail at otherwise equal settings.
      json non_lod = settings;
      non_lod.erase("lod");
      non_lod.erase("lod_error_px");
      if (settings["lod"] == "full") full_detail[non_lod.dump()] = img;
      const auto full = full_detail.find(non_lod.dump());
      if (full != full_detail.end()) {
        const PixelError vs_full = compare_images(full->second, img);
        p.lod_vs_full_pct_off = vs_full.pct_off;
        p.lod_vs_full_blob = vs_full.largest_blob;
      }
      p.is_default = settings == result.defaults;
      std::fprintf(stderr, "  %-14s %-12s server %8.2f ms  wall %8.2f ms  error %.4f%s  [%s]\n", p.family.c_str(),
                   p.label.c_str(), p.server_ms, p.wall_ms, scene.analytic ? p.band_edge_px : p.pct_off,
                   scene.analytic ? " px" : " %", p.lod_header.c_str());
      result.points.push_back(p);
      panel.points.push_back({p.label, p.family, p.server_ms, p.server_p25_ms, p.server_p75_ms,
                              scene.analytic ? p.band_edge_px : p.pct_off, p.png_bytes, p.is_default, false});
    }
    mark_pareto_front(panel.points);
    // Copy the front back to the points of this scene (same order).
    std::size_t first = result.points.size() - panel.points.size();
    for (std::size_t i = 0; i < panel.points.size(); ++i) result.points[first + i].on_front = panel.points[i].on_front;
    result.panels.push_back(std::move(panel));
  }
  return result;
}

void write_sweep_csv(const SweepResult& result, const std::filesystem::path& path) {
  std::ofstream out(path);
  out << "scene,family,label,msaa,supersample,lod,lod_error_px,map_size,png_compression,lod_drawn,"
         "server_ms,server_p25_ms,server_p75_ms,wall_ms,png_ms,png_bytes,mean_abs_error,pct_pixels_off,"
         "band_edge_px,band_edge_max_px,"
         "lod_vs_full_pct_off,lod_vs_full_blob_px,default,on_front\n";
  for (const SweepPoint& p : result.points) {
    const json& s = p.settings;
    char line[512];
    std::snprintf(
        line, sizeof line,
        "\"%s\",%s,\"%s\",%d,%d,%s,%g,%d,%d,\"%s\",%.3f,%.3f,%.3f,%.3f,%.3f,%zu,%.4f,%.4f,%.4f,%.4f,%.4f,%zu,%d,%d\n",
        p.scene.c_str(), p.family.c_str(), p.label.c_str(), s["msaa"].get<int>(), s["supersample"].get<int>(),
        s["lod"].get<std::string>().c_str(), s["lod_error_px"].get<double>(), s["map_size"].get<int>(),
        s["png_compression"].get<int>(), p.lod_header.c_str(), p.server_ms, p.server_p25_ms, p.server_p75_ms, p.wall_ms,
        p.png_ms, p.png_bytes, p.mean_abs, p.pct_off, p.band_edge_px, p.band_edge_max_px, p.lod_vs_full_pct_off,
        p.lod_vs_full_blob, p.is_default ? 1 : 0, p.on_front ? 1 : 0);
    out << line;
  }
}

nlohmann::json sweep_json(const SweepResult& result) {
  json points = json::array();
  for (const SweepPoint& p : result.points) {
    points.push_back({{"scene", p.scene},
                      {"family", p.family},
                      {"label", p.label},
                      {"settings", p.settings},
                      {"lod_drawn", p.lod_header},
                      {"server_ms", p.server_ms},
                      {"server_p25_ms", p.server_p25_ms},
                      {"server_p75_ms", p.server_p75_ms},
                      {"wall_ms", p.wall_ms},
                      {"png_ms", p.png_ms},
                      {"png_bytes", p.png_bytes},
                      {"mean_abs_error", p.mean_abs},
                      {"pct_pixels_off", p.pct_off},
                      {"band_edge_px", p.band_edge_px},
                      {"band_edge_max_px", p.band_edge_max_px},
                      {"lod_vs_full_pct_off", p.lod_vs_full_pct_off},
                      {"lod_vs_full_blob_px", p.lod_vs_full_blob},
                      {"default", p.is_default},
                      {"on_front", p.on_front}});
  }
  return {{"defaults", result.defaults}, {"points", points}};
}

}  // namespace toond::bench
