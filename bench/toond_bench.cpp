// toond_bench: time against error for every quality knob, scaling with
// triangles and pixels, throughput under load, and toond's half of the
// three.js comparison. Starts its own toond (the one built beside it) on
// 127.0.0.1:0 and writes CSV, JSON and an SVG plot.
#include <cstdio>
#include <fstream>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include "bench_http.h"
#include "crease_ratios.h"
#include "floor_ratios.h"
#include "pareto_plot.h"
#include "quality_sweep.h"
#include "scaling.h"
#include "support/daemon.h"
#include "throughput.h"
#include "versus.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace toond::bench;

constexpr const char* kUsage = R"(usage: toond_bench [options] [PART...]
Parts (default: sweep scaling load):
  sweep     every quality knob (msaa 1/2/4/8 x supersample 1-4, LOD budget,
            shadow-map size, PNG level) over the analytic sphere, spot, the
            bunny, the windmill and a shadowed floor: median server time
            (Server-Timing) and request-to-PNG time, error against each
            scene's reference (supersample 4 x msaa 8, map 4096, lod full);
            a scene's points are timed in up to three interleaved rounds;
            the Pareto front allows for the repeats' spread and PNG size;
            sweep.csv, sweep.json, time_vs_error.svg
  scaling   server time against triangles (generated spheres 1k-1M) and
            pixels (256^2-2048^2), fitted exponents; scaling.csv/.json
  load      requests/s and p50/p99 at 1, 4 and 16 clients; load.json
  versus    toond's half of bench/threejs/compare.mjs; versus.json
  floor     the default request over its geometry floor (bunny and spot
            512², interleaved), the PNG encode at 512² and 1024², and
            renders/s at 1 and 16 clients against a second daemon with
            --frames-in-flight 2; floor.json
  creases   the demo's, the hard-edged shared models' and Minetest's player's
            (at rest and walking) default request at 512² against the
            same with creases never, interleaved; creases.json
Options:
  --quick          fewer points and repeats (about a minute)
  --smoke          one tiny render per part that has one (a test of the driver)
  --repeats N      timed repeats per point (default 5; quick 2)
  --out DIR        where results go (default bench/results)
  --models DIR     the shared models (default: ../shared/models beside the checkout)
  --render-threads N  the daemon's --render-threads (default: its own default)
  --frames-in-flight N  the daemon's --frames-in-flight (default: its own default)
  --toond PATH     ignored; the toond built with this driver is used
)";

struct Args {
  bool quick = false;
  bool smoke = false;
  int repeats = 0;
  fs::path out = "bench/results";
  fs::path models = TOOND_SHARED_MODELS;
  std::string render_threads;    // empty: the daemon's default
  std::string frames_in_flight;  // empty: the daemon's default
  std::set<std::string> parts;
};

Args parse(int argc, char** argv) {
  Args a;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--quick")
      a.quick = true;
    else if (arg == "--smoke")
      a.smoke = true;
    else if (arg == "--repeats")
      a.repeats = std::stoi(value());
    else if (arg == "--out")
      a.out = value();
    else if (arg == "--models")
      a.models = value();
    else if (arg == "--render-threads")
      a.render_threads = value();
    else if (arg == "--frames-in-flight")
      a.frames_in_flight = value();
    else if (arg == "--toond")
      value();
    else if (arg == "-h" || arg == "--help") {
      std::cout << kUsage;
      std::exit(0);
    } else if (arg == "sweep" || arg == "scaling" || arg == "load" || arg == "versus" || arg == "floor" ||
               arg == "creases") {
      a.parts.insert(arg);
    } else
      throw std::invalid_argument("unknown argument " + arg);
  }
  if (a.parts.empty())
    a.parts = a.smoke ? std::set<std::string>{"sweep"} : std::set<std::string>{"sweep", "scaling", "load"};
  if (a.repeats <= 0) a.repeats = a.smoke ? 1 : a.quick ? 2 : 5;
  return a;
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  std::cerr << "bench: wrote " << path.string() << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Args args = parse(argc, argv);
    fs::create_directories(args.out);
    // Every point is rendered several times with identical parameters: the
    // result cache would answer all but the first from memory.
    std::vector<std::string> daemon_args = {"--result-cache-mb", "0"};
    if (!args.render_threads.empty()) daemon_args.insert(daemon_args.end(), {"--render-threads", args.render_threads});
    if (!args.frames_in_flight.empty()) {
      daemon_args.insert(daemon_args.end(), {"--frames-in-flight", args.frames_in_flight});
    }
    toond::test::Daemon daemon({}, daemon_args);
    httplib::Client client(daemon.url());
    client.set_read_timeout(300);
    client.set_write_timeout(300);
    json summary = {{"quick", args.quick},
                    {"repeats", args.repeats},
                    {"render_threads", args.render_threads},
                    {"frames_in_flight", args.frames_in_flight}};
    if (auto health = client.Get("/healthz"); health && health->status == 200) {
      summary["gl"] = json::parse(health->body)["gl"];
    }
    const bool have_models = fs::is_directory(args.models);
    if (args.parts.count("sweep")) {
      SweepOptions o{args.quick, args.repeats, have_models ? args.models : fs::path(), args.smoke};
      const SweepResult sweep = run_quality_sweep(client, o);
      write_sweep_csv(sweep, args.out / "sweep.csv");
      write_text(args.out / "sweep.json", sweep_json(sweep).dump(1));
      write_text(
          args.out / "time_vs_error.svg",
          svg_time_vs_error(sweep.panels, std::string("toond_bench") + (args.quick ? " --quick" : "") + ", median of " +
                                              std::to_string(args.repeats) + " renders per point, 512x512, " +
                                              summary.value("/gl/renderer"_json_pointer, std::string("?"))));
    }
    if (args.parts.count("scaling")) {
      const ScalingResult scaling =
          run_scaling(client, {args.quick, args.repeats, have_models ? args.models : fs::path()});
      write_scaling_csv(scaling, args.out / "scaling.csv");
      write_text(args.out / "scaling.json", scaling_json(scaling).dump(1));
    }
    if (args.parts.count("load") && have_models) {
      std::cerr << "bench: load (bunny 512², default settings)\n";
      const json params = {
          {"model", upload_folder(client, args.models / "stanford-bunny")}, {"width", 512}, {"height", 512}};
      const auto levels = run_throughput(daemon.url(), params, {1, 4, 16}, args.quick ? 2.0 : 6.0);
      write_text(args.out / "load.json", throughput_json(levels).dump(1));
    }
    if (args.parts.count("versus") && have_models) {
      const json versus = run_versus(client, daemon.url(), args.models, args.repeats * 4, args.quick ? 2.0 : 6.0);
      write_text(args.out / "versus.json", versus.dump(1));
    }
    if (args.parts.count("floor") && have_models) {
      const json floor =
          run_floor_ratios(client, daemon.url(), daemon_args, args.models, args.repeats * 4, args.quick ? 2.0 : 6.0);
      write_text(args.out / "floor.json", floor.dump(1));
    }
    if (args.parts.count("creases") && have_models) {
      write_text(args.out / "creases.json", run_crease_ratios(client, args.models, args.repeats * 4).dump(1));
    }
    write_text(args.out / "run.json", summary.dump(1));
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "toond_bench: " << e.what() << "\n";
    return 1;
  }
}
