#include "crease_ratios.h"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include "bench_http.h"
#include "stats.h"

namespace toond::bench {
namespace {

using nlohmann::json;

// Server time (every Server-Timing entry but the queue) of `request` (a
// default one at 512², but for what it adds) and of the same without
// crease lines, rendered in turn so the machine's drift falls on both
// alike.
json with_and_without_creases(httplib::Client& client, const json& adding, int repeats) {
  json request = {{"width", 512}, {"height", 512}};
  request.update(adding);
  json never = request;
  never["outline"] = {{"creases", "never"}};
  for (int warm = 0; warm < 2; ++warm) {  // the model's upload, the programs
    render_timed(client, request);
    render_timed(client, never);
  }
  std::vector<double> creased, bare;
  for (int i = 0; i < repeats; ++i) {
    creased.push_back(render_timed(client, request).server_ms);
    bare.push_back(render_timed(client, never).server_ms);
  }
  return {{"default_ms", median(creased)},           {"never_ms", median(bare)},
          {"ratio", median(creased) / median(bare)}, {"default_p90_ms", percentile(creased, 0.9)},
          {"never_p90_ms", percentile(bare, 0.9)},   {"repeats", repeats}};
}

}  // namespace

json run_crease_ratios(httplib::Client& client, const std::filesystem::path& models, int repeats) {
  std::cerr << "bench: crease lines against creases never (512², default request, interleaved)\n";
  // The demo model (no model given), whose sphere sinks into its box, the
  // hard-edged shared models, and Minetest's player (boxes pushed into one
  // another) at rest and walking: posed, the seams found at rest are not
  // where its parts cross, and the screen-space pass finds its lines.
  std::ifstream b3d(std::filesystem::path(TOOND_EXPORTED) / "minetest" / "character.b3d", std::ios::binary);
  const std::string player = upload_obj(client, std::string(std::istreambuf_iterator<char>(b3d), {}), "character.b3d");
  std::vector<std::pair<std::string, json>> requests = {{"demo", json::object()}};
  for (const char* name : {"windmill", "kenney-space-craft", "kenney-cube-pet-dog"}) {
    requests.emplace_back(name, json{{"model", upload_folder(client, models / name)}});
  }
  requests.emplace_back("minetest-player", json{{"model", player}});
  requests.emplace_back("minetest-player-walking",
                        json{{"model", player}, {"animation", {{"clip", 0}, {"time", 177.0 / 60.0}}}});
  json out;
  for (const auto& [name, adding] : requests) {
    const json r = with_and_without_creases(client, adding, repeats);
    std::fprintf(stderr, "  %-24s default %7.2f ms, creases never %7.2f ms, ratio %.3f (medians of %d)\n", name.c_str(),
                 r["default_ms"].get<double>(), r["never_ms"].get<double>(), r["ratio"].get<double>(), repeats);
    out[name] = r;
  }
  return out;
}

}  // namespace toond::bench
