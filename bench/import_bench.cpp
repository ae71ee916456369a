// toond_import_bench: how long the importer takes for the same mesh as a
// binary glTF and as an OBJ. The mesh is a UV sphere made here (no shared
// model is large enough for a 10 MB GLB), or an OBJ file given with --obj;
// the GLB is its twin written by the tests' glTF writer. Each import runs
// `--repeats` times, the four kinds interleaved so that the machine's drift
// falls on all of them alike, and the medians are printed with the files'
// sizes: the format's own importer alone, and import_bundle (what an upload
// runs) with the levels of detail and enclosure every upload also gets.
// `--write DIR` leaves the two files there for bench/upload_cost.sh.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

#include "scene/bundle.h"
#include "scene/bundle_import.h"
#include "scene/gltf_import.h"
#include "scene/obj_import.h"
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
Prints, for the OBJ and the GLB, the bytes and the median, first and third
quartile of the wall-clock time of each importer alone and of import_bundle,
and the GLB / OBJ ratios.
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
    if (i + 1 >= argc) usage_error(flag == "--segments" || flag == "--obj" || flag == "--repeats" ||
                                           flag == "--write"
                                       ? flag + " wants a value"
                                       : "unknown option " + flag);
    const char* value = argv[++i];
    if (flag == "--segments") o.segments = positive(flag, value);
    else if (flag == "--repeats") o.repeats = positive(flag, value);
    else if (flag == "--obj") o.obj_file = value;
    else if (flag == "--write") o.write_dir = value;
    else usage_error("unknown option " + flag);
  }
  if (o.segments < 4) usage_error("--segments wants at least 4");
  return o;
}

struct Timings {
  std::vector<double> seconds;
  void add(const std::function<void()>& work) {
    const auto start = Clock::now();
    work();
    seconds.push_back(std::chrono::duration<double>(Clock::now() - start).count());
  }
  double median() const { return bench::median(seconds); }
  std::string summary() const {
    char text[64];
    std::snprintf(text, sizeof text, "%8.1f ms (%.1f-%.1f)", median() * 1e3, bench::percentile(seconds, 0.25) * 1e3,
                  bench::percentile(seconds, 0.75) * 1e3);
    return text;
  }
};

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
  std::printf("median of %d (quartiles)        bytes  %-28s  %s\n", options.repeats, "importer alone",
              "import_bundle (with LODs)");
  std::printf("%-22s %12zu  %-28s  %s\n", "OBJ", obj.total_bytes(), obj_only.summary().c_str(),
              obj_full.summary().c_str());
  std::printf("%-22s %12zu  %-28s  %s\n", "GLB", glb.total_bytes(), glb_only.summary().c_str(),
              glb_full.summary().c_str());
  std::printf("%-22s %12.2f  %8.2f%-20s  %8.2f\n", "GLB / OBJ", glb_mb / obj_mb, glb_only.median() / obj_only.median(),
              "", glb_full.median() / obj_full.median());
  std::printf("MB/s, importer alone: OBJ %.1f, GLB %.1f\n", obj_mb / obj_only.median(), glb_mb / glb_only.median());
  return 0;
}
