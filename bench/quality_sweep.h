#pragma once
// The time-against-error sweep: every quality knob over the analytic sphere
// and real models, each point timed (median of repeats) and compared with
// the scene's reference render.
#include <filesystem>
#include <string>
#include <vector>

#include <httplib.h>
#include <nlohmann/json.hpp>

#include "pareto_plot.h"

namespace toond::bench {

struct SweepOptions {
  bool quick = false;
  int repeats = 5;
  std::filesystem::path models;  // ../shared/models; scenes from it are left out when absent
  bool smoke = false;            // one tiny point, one repeat: proves the driver runs
};

struct SweepPoint {
  std::string scene;
  std::string family;
  std::string label;
  nlohmann::json settings;  // msaa, supersample, lod, lod_error_px, map_size, png_compression
  std::string lod_header;
  double wall_ms = 0;
  double server_ms = 0;
  double server_p25_ms = 0;  // the repeats' interquartile range
  double server_p75_ms = 0;
  double png_ms = 0;
  std::size_t png_bytes = 0;
  double mean_abs = 0;
  double pct_off = 0;
  double band_edge_px = -1;  // sphere only
  double band_edge_max_px = -1;
  double lod_vs_full_pct_off = -1;   // lod family: against lod full at the same settings
  std::size_t lod_vs_full_blob = 0;  // and its largest connected group of off pixels
  bool is_default = false;
  bool on_front = false;
};

struct SweepResult {
  std::vector<SweepPoint> points;
  std::vector<PlotPanel> panels;
  nlohmann::json defaults;  // the schema's defaults of the swept knobs
};

SweepResult run_quality_sweep(httplib::Client& client, const SweepOptions& options);

void write_sweep_csv(const SweepResult& result, const std::filesystem::path& path);
nlohmann::json sweep_json(const SweepResult& result);

}  // namespace toond::bench
