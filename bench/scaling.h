#pragma once
// How render time grows: against triangles (generated spheres, 1k → 1M) and
// against pixels (256² → 2048²), with the fitted exponent of each.
#include <filesystem>
#include <string>
#include <vector>

#include <httplib.h>
#include <nlohmann/json.hpp>

namespace toond::bench {

struct ScalingRow {
  std::string axis;  // "triangles" or "pixels"
  double size = 0;   // triangles, or pixels per image
  std::string label;
  double server_ms_full = 0;  // lod full
  double server_ms_auto = 0;  // lod auto (default budget)
  double wall_ms_full = 0;
  std::string lod_auto;  // X-Toond-Lod of the auto render
};

struct ScalingResult {
  std::vector<ScalingRow> rows;
  double triangle_exponent_full = 0;  // server time ∝ triangles^e, lod full
  double triangle_exponent_auto = 0;
  double pixel_exponent_full = 0;  // server time ∝ pixels^e
  double pixel_exponent_auto = 0;
};

struct ScalingOptions {
  bool quick = false;
  int repeats = 5;
  std::filesystem::path models;  // the pixel axis renders the bunny when present, else a sphere
};

ScalingResult run_scaling(httplib::Client& client, const ScalingOptions& options);
nlohmann::json scaling_json(const ScalingResult& result);
void write_scaling_csv(const ScalingResult& result, const std::filesystem::path& path);

}  // namespace toond::bench
