#include "floor_ratios.h"

#include <cstdio>
#include <iostream>

#include "bench_http.h"
#include "stats.h"
#include "support/daemon.h"
#include "throughput.h"

namespace toond::bench {
namespace {

using nlohmann::json;

// Server time (every Server-Timing entry but the queue) of the default
// request, of the same without the outline and without outline and
// specular (what no way of drawing those two could go below), and of its
// floor, rendered in turn so the machine's drift falls on all alike.
json default_over_floor(httplib::Client& client, const std::string& model, int repeats) {
  const json request = {{"model", model}, {"width", 512}, {"height", 512}};
  json without_outline = request;
  without_outline["outline"] = {{"enabled", false}};
  json without_outline_or_specular = without_outline;
  without_outline_or_specular["specular"] = {{"enabled", false}};
  const std::vector<json> requests = {request, without_outline, without_outline_or_specular,
                                      geometry_floor_request(request)};
  for (const json& r : requests) render_timed(client, r);  // warm: the model's upload, the programs
  std::vector<std::vector<double>> ms(requests.size());
  TimedRender last;
  for (int i = 0; i < repeats; ++i) {
    for (std::size_t k = 0; k < requests.size(); ++k) {
      const TimedRender timed = render_timed(client, requests[k]);
      ms[k].push_back(timed.server_ms);
      if (k == 0) last = timed;
    }
  }
  const double floor = median(ms[3]);
  return {{"default_ms", median(ms[0])},
          {"floor_ms", floor},
          {"ratio", median(ms[0]) / floor},
          {"without_outline_ms", median(ms[1])},
          {"without_outline_ratio", median(ms[1]) / floor},
          {"without_outline_or_specular_ms", median(ms[2])},
          {"without_outline_or_specular_ratio", median(ms[2]) / floor},
          {"lod_drawn", last.lod}};
}

json png_times(httplib::Client& client, const std::string& model, int repeats) {
  json out = json::object();
  for (int size : {512, 1024}) {
    const json request = {{"model", model}, {"width", size}, {"height", size}};
    render_timed(client, request);
    std::vector<double> png;
    for (int i = 0; i < repeats; ++i) png.push_back(render_timed(client, request).png_ms);
    out[std::to_string(size)] = {{"median_ms", median(png)}, {"p90_ms", percentile(png, 0.9)}};
  }
  return out;
}

// Renders/s of each daemon at each client count, two rounds, alternating.
json in_flight_throughput(const std::string& url, const std::string& url_in_flight, const json& request,
                          double seconds) {
  json rounds = json::array();
  for (int round = 0; round < 2; ++round) {
    for (const auto& [name, at] :
         {std::pair{"frames_in_flight_1", url}, std::pair{"frames_in_flight_2", url_in_flight}}) {
      for (const LoadLevel& level : run_throughput(at, request, {1, 16}, seconds)) {
        rounds.push_back({{"daemon", name},
                          {"round", round},
                          {"clients", level.clients},
                          {"renders_per_s", level.requests_per_s},
                          {"p50_ms", level.p50_ms},
                          {"failures", level.failures}});
        std::fprintf(stderr, "  %s, %2d clients: %7.1f renders/s, p50 %6.2f ms\n", name, level.clients,
                     level.requests_per_s, level.p50_ms);
      }
    }
  }
  return rounds;
}

}  // namespace

json geometry_floor_request(json params) {
  params["shading"] = {{"mode", "flat"}, {"base", "white"}};
  params["outline"] = {{"enabled", false}};
  params["contour"] = {{"enabled", false}};
  params["specular"] = {{"enabled", false}};
  params["rim"] = {{"enabled", false}};
  params["shadows"] = {{"enabled", false}};
  return params;
}

json run_floor_ratios(httplib::Client& client, const std::string& url, const std::vector<std::string>& daemon_args,
                      const std::filesystem::path& models, int repeats, double load_seconds) {
  std::cerr << "bench: the default request against its geometry floor (512²)\n";
  json out;
  std::string bunny;
  for (const char* name : {"stanford-bunny", "spot"}) {
    const std::string model = upload_folder(client, models / name);
    if (std::string(name) == "stanford-bunny") bunny = model;
    const json r = default_over_floor(client, model, repeats);
    std::fprintf(stderr,
                 "  %-15s default %7.2f ms, floor %7.2f ms, ratio %.2f  [%s]\n"
                 "  %-15s without the outline %.2f, without outline and specular %.2f (what those two leave)\n",
                 name, r["default_ms"].get<double>(), r["floor_ms"].get<double>(), r["ratio"].get<double>(),
                 r["lod_drawn"].get<std::string>().c_str(), "", r["without_outline_ratio"].get<double>(),
                 r["without_outline_or_specular_ratio"].get<double>());
    out["default_over_floor"][name] = r;
  }
  out["png"] = png_times(client, bunny, repeats);
  std::fprintf(stderr, "  png (bunny, default request): 512² %.2f ms, 1024² %.2f ms\n",
               out["png"]["512"]["median_ms"].get<double>(), out["png"]["1024"]["median_ms"].get<double>());
  if (load_seconds > 0) {
    std::vector<std::string> in_flight_args = daemon_args;
    in_flight_args.insert(in_flight_args.end(), {"--frames-in-flight", "2"});
    test::Daemon in_flight({}, in_flight_args);
    httplib::Client second(in_flight.url());
    second.set_read_timeout(300);
    const std::string model = upload_folder(second, models / "stanford-bunny");
    if (model != bunny) throw std::runtime_error("the two daemons gave the bunny different ids");
    const json request = {{"model", bunny}, {"width", 512}, {"height", 512}};
    out["in_flight"] = in_flight_throughput(url, in_flight.url(), request, load_seconds);
  }
  return out;
}

}  // namespace toond::bench
