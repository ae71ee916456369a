#include "scaling.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>

#include "bench_http.h"
#include "stats.h"

namespace toond::bench {
namespace {

using nlohmann::json;

// A closed UV sphere of about `triangles` triangles, positions only (the
// importer makes the normals), written short so 1M triangles stay ~40 MB.
std::string sphere_of(std::size_t triangles) {
  // 2·seg·(rings − 1) triangles with seg = 2·rings.
  const int rings = std::max(4, static_cast<int>(std::lround(std::sqrt(triangles / 4.0))));
  const int segments = 2 * rings;
  const double pi = std::acos(-1.0);
  std::string obj;
  obj.reserve(static_cast<std::size_t>(rings) * segments * 64);
  char line[96];
  std::snprintf(line, sizeof line, "v 0 1 0\n");
  obj += line;
  for (int r = 1; r < rings; ++r) {
    const double theta = pi * r / rings;
    for (int s = 0; s < segments; ++s) {
      const double phi = 2.0 * pi * s / segments;
      std::snprintf(line, sizeof line, "v %.7g %.7g %.7g\n", std::sin(theta) * std::cos(phi), std::cos(theta),
                    -std::sin(theta) * std::sin(phi));
      obj += line;
    }
  }
  obj += "v 0 -1 0\n";
  const int south = 2 + (rings - 1) * segments;
  auto at = [&](int r, int s) { return 2 + (r - 1) * segments + (s % segments); };
  for (int s = 0; s < segments; ++s) {
    std::snprintf(line, sizeof line, "f 1 %d %d\n", at(1, s), at(1, s + 1));
    obj += line;
    std::snprintf(line, sizeof line, "f %d %d %d\n", south, at(rings - 1, s + 1), at(rings - 1, s));
    obj += line;
  }
  for (int r = 1; r + 1 < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      std::snprintf(line, sizeof line, "f %d %d %d\nf %d %d %d\n", at(r, s), at(r + 1, s), at(r + 1, s + 1), at(r, s),
                    at(r + 1, s + 1), at(r, s + 1));
      obj += line;
    }
  }
  return obj;
}

struct Timing {
  double server = 0, wall = 0;
  std::string lod;
};

Timing time_render(httplib::Client& client, const json& params, int repeats) {
  render_timed(client, params);  // warm
  std::vector<double> server, wall;
  Timing t;
  for (int i = 0; i < repeats; ++i) {
    const TimedRender r = render_timed(client, params);
    server.push_back(r.server_ms);
    wall.push_back(r.wall_ms);
    t.lod = r.lod;
  }
  t.server = median(server);
  t.wall = median(wall);
  return t;
}

ScalingRow measure_row(httplib::Client& client, const std::string& axis, double size, const std::string& label,
                       json params, int repeats) {
  ScalingRow row;
  row.axis = axis;
  row.size = size;
  row.label = label;
  params["lod"] = "full";
  const Timing full = time_render(client, params, repeats);
  params["lod"] = "auto";
  const Timing automatic = time_render(client, params, repeats);
  row.server_ms_full = full.server;
  row.wall_ms_full = full.wall;
  row.server_ms_auto = automatic.server;
  row.lod_auto = automatic.lod;
  std::fprintf(stderr, "  %-9s %-12s full %8.2f ms  auto %8.2f ms  [%s]\n", axis.c_str(), label.c_str(), full.server,
               automatic.server, automatic.lod.c_str());
  return row;
}

}  // namespace

ScalingResult run_scaling(httplib::Client& client, const ScalingOptions& o) {
  ScalingResult result;
  std::cerr << "bench: scaling with triangles\n";
  std::vector<std::size_t> counts = {1000, 4000, 16000, 64000, 256000};
  if (!o.quick) counts.push_back(1000000);
  std::vector<double> tri_x, tri_full, tri_auto;
  for (std::size_t n : counts) {
    const std::string id = upload_obj(client, sphere_of(n), "sphere.obj");
    auto info = client.Get("/models/" + id);
    const double triangles = info && info->status == 200 ? json::parse(info->body).value("triangles", double(n)) : n;
    char label[32];
    std::snprintf(label, sizeof label, "%.0fk tris", triangles / 1000.0);
    ScalingRow row = measure_row(client, "triangles", triangles, label, {{"model", id}}, o.repeats);
    tri_x.push_back(triangles);
    tri_full.push_back(row.server_ms_full);
    tri_auto.push_back(row.server_ms_auto);
    result.rows.push_back(row);
    client.Delete("/models/" + id);
  }
  // The exponent over the upper half, where the triangles dominate a fixed
  // per-render cost.
  const std::size_t half = tri_x.size() / 2;
  result.triangle_exponent_full =
      growth_exponent({tri_x.begin() + half, tri_x.end()}, {tri_full.begin() + half, tri_full.end()});
  result.triangle_exponent_auto =
      growth_exponent({tri_x.begin() + half, tri_x.end()}, {tri_auto.begin() + half, tri_auto.end()});

  std::cerr << "bench: scaling with pixels\n";
  const bool have_bunny = !o.models.empty() && std::filesystem::is_directory(o.models / "stanford-bunny");
  const std::string model = have_bunny ? upload_folder(client, o.models / "stanford-bunny")
                                       : upload_obj(client, sphere_of(64000), "sphere.obj");
  std::vector<int> sizes = {256, 512, 1024};
  if (!o.quick) sizes.push_back(2048);
  std::vector<double> px_x, px_full, px_auto;
  for (int s : sizes) {
    const std::string label = std::to_string(s) + "²" + (have_bunny ? " bunny" : " sphere");
    ScalingRow row =
        measure_row(client, "pixels", double(s) * s, label, {{"model", model}, {"width", s}, {"height", s}}, o.repeats);
    px_x.push_back(double(s) * s);
    px_full.push_back(row.server_ms_full);
    px_auto.push_back(row.server_ms_auto);
    result.rows.push_back(row);
  }
  result.pixel_exponent_full = growth_exponent({px_x.begin() + 1, px_x.end()}, {px_full.begin() + 1, px_full.end()});
  result.pixel_exponent_auto = growth_exponent({px_x.begin() + 1, px_x.end()}, {px_auto.begin() + 1, px_auto.end()});
  return result;
}

nlohmann::json scaling_json(const ScalingResult& r) {
  json rows = json::array();
  for (const ScalingRow& row : r.rows) {
    rows.push_back({{"axis", row.axis},
                    {"size", row.size},
                    {"label", row.label},
                    {"server_ms_lod_full", row.server_ms_full},
                    {"server_ms_lod_auto", row.server_ms_auto},
                    {"wall_ms_lod_full", row.wall_ms_full},
                    {"lod_auto_drawn", row.lod_auto}});
  }
  return {{"rows", rows},
          {"exponent",
           {{"triangles_lod_full", r.triangle_exponent_full},
            {"triangles_lod_auto", r.triangle_exponent_auto},
            {"pixels_lod_full", r.pixel_exponent_full},
            {"pixels_lod_auto", r.pixel_exponent_auto}}}};
}

void write_scaling_csv(const ScalingResult& r, const std::filesystem::path& path) {
  std::ofstream out(path);
  out << "axis,size,label,server_ms_lod_full,server_ms_lod_auto,wall_ms_lod_full,lod_auto_drawn\n";
  for (const ScalingRow& row : r.rows) {
    char line[256];
    std::snprintf(line, sizeof line, "%s,%.0f,\"%s\",%.3f,%.3f,%.3f,\"%s\"\n", row.axis.c_str(), row.size,
                  row.label.c_str(), row.server_ms_full, row.server_ms_auto, row.wall_ms_full, row.lod_auto.c_str());
    out << line;
  }
}

}  // namespace toond::bench
