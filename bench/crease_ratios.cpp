#include "crease_ratios.h"

#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "bench_http.h"
#include "stats.h"

namespace toond::bench {
namespace {

using nlohmann::json;

// Server time (every Server-Timing entry but the queue) of the default
// request and of the same without crease lines, rendered in turn so the
// machine's drift falls on both alike.
json with_and_without_creases(httplib::Client& client, const std::string& model, int repeats) {
  const json request = {{"model", model}, {"width", 512}, {"height", 512}};
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
  return {{"default_ms", median(creased)},
          {"never_ms", median(bare)},
          {"ratio", median(creased) / median(bare)},
          {"default_p90_ms", percentile(creased, 0.9)},
          {"never_p90_ms", percentile(bare, 0.9)},
          {"repeats", repeats}};
}

}  // namespace

json run_crease_ratios(httplib::Client& client, const std::filesystem::path& models, int repeats) {
  std::cerr << "bench: crease lines against creases never (512², default request, interleaved)\n";
  json out;
  for (const char* name : {"windmill", "kenney-space-craft", "kenney-cube-pet-dog"}) {
    const json r = with_and_without_creases(client, upload_folder(client, models / name), repeats);
    std::fprintf(stderr, "  %-20s default %7.2f ms, creases never %7.2f ms, ratio %.3f (medians of %d)\n", name,
                 r["default_ms"].get<double>(), r["never_ms"].get<double>(), r["ratio"].get<double>(), repeats);
    out[name] = r;
  }
  return out;
}

}  // namespace toond::bench
