// toond_import_bench: how long the importer takes for the same mesh as a
// binary glTF and as an OBJ. The mesh is a UV sphere made here (no shared
// model is large enough for a 10 MB GLB), or an OBJ file given with --obj;
// the GLB is its twin written by the tests' glTF writer. Each import runs
// `--repeats` times, the four kinds interleaved so that the machine's drift
// falls on all of them alike, and the medians (wall-clock and CPU time) are
// printed with the files' sizes: the format's own importer alone, and
// import_bundle (what an upload runs) with the levels of detail and
// enclosure every upload also gets.
// `--write DIR` leaves the two files there for bench/upload_cost.sh.
#include <time.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include "scene/gltf/gltf_import.h"
#include "scene/import/bundle_import.h"
#include "scene/import/obj_import.h"
#include "scene/reading/bundle.h"
#include "stats.h"
#include "support/generated_models.h"
#include "support/gltf_twin.h"

namespace {

namespace fs = std::filesystem;
using namespace toond;
using Clock = std::chrono::steady_clock;

constexpr const char* kUsage = R"(usage: toond_import_bench [options]
  --segments N   the generated sphere's segments (rings: N/2); default 640,
                 408,320 triangles: an 11.5 MB GLB, a 44 MB OBJ
  --obj FILE     time this OBJ file instead (alone: no MTL, no textures)
  --repeats N    imports of each kind, interleaved; default 7
  --write DIR    also write the OBJ and the GLB into DIR (for
                 bench/upload_cost.sh, which uploads them to a toond)
Prints, for the OBJ and the GLB, the bytes, and for each importer alone and
for import_bundle the median, first and third quartile of the wall-clock
time and the median CPU time of the process; then the GLB / OBJ ratios.
)";

struct Options {
  int segments = 640;
  int repeats = 7;
  std::string obj_file;
  std::string write_dir;
};

[[noreturn]] void usage_error(const std::string& message) {
  std::fprintf(stderr, "toond_import_bench: %s\n%s", message.c_str(), kUsage);
  std::exit(2);
}

int positive(const std::string& flag, const char* text) {
  char* end = nullptr;
  const long v = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || v < 1 || v > 100000) usage_error(flag + " wants a whole number from 1");
  return static_cast<int>(v);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--help" || flag == "-h") {
      std::fputs(kUsage, stdout);
      std::exit(0);
    }
    if (i + 1 >= argc)
      usage_error(flag == "--segments" || flag == "--obj" || flag == "--repeats" || flag == "--write"
                      ? flag + " wants a value"
                      : "unknown option " + flag);
    const char* value = argv[++i];
    if (flag == "--segments")
      o.segments = positive(flag, value);
    else if (flag == "--repeats")
      o.repeats = positive(flag, value);
    else if (flag == "--obj")
      o.obj_file = value;
    else if (flag == "--write")
      o.write_dir = value;
    else
      usage_error("unknown option " + flag);
  }
  if (o.segments < 4) usage_error("--segments wants at least 4");
  return o;
}

// CPU time of the whole process: an import runs on the calling thread, and
// what else a busy machine runs does not count here, as it does in the
// wall-clock time.
double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec) / 1e9;
}

struct Timings {
  std::vector<double> wall, cpu;
  void add(const std::function<void()>& work) {
    const auto start = Clock::now();
    const double cpu_start = process_cpu_seconds();
    work();
    cpu.push_back(process_cpu_seconds() - cpu_start);
    wall.push_back(std::chrono::duration<double>(Clock::now() - start).count());
  }
  // "wall median (quartiles)  CPU median", milliseconds.
  std::string summary() const {
    char quartiles[48], text[96];
    std::snprintf(quartiles, sizeof quartiles, "(%.1f-%.1f)", bench::percentile(wall, 0.25) * 1e3,
                  bench::percentile(wall, 0.75) * 1e3);
    std::snprintf(text, sizeof text, "%8.1f %-18s %8.1f", bench::median(wall) * 1e3, quartiles,
                  bench::median(cpu) * 1e3);
    return text;
  }
};

// "wall ratio  CPU ratio" of the medians.
std::string ratios(const Timings& glb, const Timings& obj) {
  char text[64];
  std::snprintf(text, sizeof text, "%8.2f %-18s %8.2f", bench::median(glb.wall) / bench::median(obj.wall), "",
                bench::median(glb.cpu) / bench::median(obj.cpu));
  return text;
}

std::string read_whole(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) usage_error("--obj " + path.string() + ": cannot read it");
  return bytes;
}

void write_files(const fs::path& dir, const scene::Bundle& bundle) {
  fs::create_directories(dir);
  for (const auto& [name, bytes] : bundle.files()) {
    std::ofstream out(dir / name, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) {
      std::fprintf(stderr, "toond_import_bench: cannot write %s\n", (dir / name).c_str());
      std::exit(1);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  scene::Bundle obj;
  std::string source;
  if (options.obj_file.empty()) {
    obj.add("sphere.obj", test::sphere_obj(options.segments, options.segments / 2));
    source = "a UV sphere of " + std::to_string(options.segments) + " segments";
  } else {
    std::error_code ec;
    if (!fs::is_regular_file(options.obj_file, ec)) usage_error("--obj " + options.obj_file + ": not a file");
    obj.add(fs::path(options.obj_file).filename().string(), read_whole(options.obj_file));
    source = options.obj_file;
  }
  const scene::Model reference = scene::import_obj_bundle(obj);
  scene::Bundle glb;
  for (auto& [name, bytes] : test::write_gltf(test::gltf_twin(reference, obj), test::GltfForm::Glb)) {
    glb.add(name, std::move(bytes));
  }
  if (!options.write_dir.empty()) {
    write_files(options.write_dir, obj);
    write_files(options.write_dir, glb);
  }
  std::printf("mesh: %s, %zu triangles, %zu vertices\n", source.c_str(), reference.mesh.triangle_count(),
              reference.mesh.positions.size());

  Timings obj_only, glb_only, obj_full, glb_full;
  for (int r = 0; r < options.repeats; ++r) {
    obj_only.add([&] { scene::import_obj_bundle(obj); });
    glb_only.add([&] { scene::import_gltf_bundle(glb, "model.glb"); });
    obj_full.add([&] { scene::import_bundle(obj); });
    glb_full.add([&] { scene::import_bundle(glb); });
  }
  const double obj_mb = static_cast<double>(obj.total_bytes()) / 1e6;
  const double glb_mb = static_cast<double>(glb.total_bytes()) / 1e6;
  std::printf("medians of %d, ms          bytes  %-36s  %s\n", options.repeats, "importer alone",
              "import_bundle (with LODs)");
  std::printf("%-18s %12s  %-36s  %s\n", "", "", "    wall (quartiles)              CPU",
              "    wall (quartiles)              CPU");
  std::printf("%-18s %12zu  %-36s  %s\n", "OBJ", obj.total_bytes(), obj_only.summary().c_str(),
              obj_full.summary().c_str());
  std::printf("%-18s %12zu  %-36s  %s\n", "GLB", glb.total_bytes(), glb_only.summary().c_str(),
              glb_full.summary().c_str());
  std::printf("%-18s %12.2f  %-36s  %s\n", "GLB / OBJ", glb_mb / obj_mb, ratios(glb_only, obj_only).c_str(),
              ratios(glb_full, obj_full).c_str());
  std::printf("MB/s, importer alone, wall: OBJ %.1f, GLB %.1f\n", obj_mb / bench::median(obj_only.wall),
              glb_mb / bench::median(glb_only.wall));
  return 0;
}
