// toond_heavy_import_bench: each heavy construct of the scaling test
// (tests/support/heavy_inputs.cpp) imported at n and 2n, as a table of
// median milliseconds and the 2n/n ratio (linear: 2; the test's bound: 2.5).
//   toond_heavy_import_bench [--scale K (default 1: the test's sizes)] [--runs N (default 5)] [--only NAME]
// With --stages NAME, one OBJ construct's import at n, step by step
// (docs/performance.md, "Heavy imports").
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "scene/import/bundle_import.h"
#include "scene/import/obj_import.h"
#include "scene/mesh/crease_edges.h"
#include "scene/mesh/crease_profile.h"
#include "scene/mesh/enclosure.h"
#include "scene/mesh/extreme_points.h"
#include "scene/mesh/mesh_lod.h"
#include "scene/mesh/mesh_processing.h"
#include "stats.h"
#include "support/import_timing.h"

namespace {

using toond::scene::Mesh;

// The median milliseconds of each step over `runs` imports of `input` at n,
// after one warm-up: the whole import, the OBJ reader (parsing and the
// mesh builder), some of the builder's steps called again on the mesh it
// built, and the steps the import runs after reading, in order. Each step
// is called through its plain public entry, as a caller without the
// import's shared position grouping would call it: the builder runs its
// steps on fewer vertices (before normals split them) or with the grouping
// it has, so their lines here are each function's own cost, not its share
// of the import.
void print_stages(const toond::test::HeavyInput& input, int n, int runs) {
  toond::test::keep_freed_memory_in_process();
  const toond::scene::Bundle bundle = input.make(n);
  std::vector<std::pair<std::string, std::vector<double>>> steps;
  std::size_t step = 0;
  const auto time = [&](const char* name, const std::function<void()>& run) {
    const double start = toond::test::thread_seconds();
    run();
    const double ms = (toond::test::thread_seconds() - start) * 1e3;
    if (step == steps.size()) steps.push_back({name, {}});
    steps[step++].second.push_back(ms);
  };
  for (int r = 0; r <= runs; ++r) {
    step = 0;
    time("import_bundle, all of it", [&] { (void)toond::scene::import_bundle(bundle); });
    toond::scene::Model model;
    time("  reading: import_obj_bundle", [&] { model = toond::scene::import_obj_bundle(bundle); });
    Mesh& mesh = model.mesh;
    time("    group_by_position", [&] { (void)toond::scene::group_by_position(mesh.positions); });
    time("    compute_outline_normals",
         [&] { (void)toond::scene::compute_outline_normals(mesh.positions, mesh.indices, mesh.normals); });
    time("    compute_tangents",
         [&] { (void)toond::scene::compute_tangents(mesh.positions, mesh.normals, mesh.texcoords, mesh.indices); });
    time("    extreme_points", [&] { (void)toond::scene::extreme_points(mesh.positions); });
    time("    measure_creases",
         [&] { (void)toond::scene::measure_creases(mesh.positions, mesh.normals, mesh.indices); });
    time("  build_lod_chain", [&] { mesh.lods = toond::scene::build_lod_chain(mesh); });
    time("  optimize_for_vertex_cache", [&] { toond::scene::optimize_for_vertex_cache(mesh); });
    time("  classify_enclosures", [&] { toond::scene::classify_enclosures(mesh); });
    time("  find_crease_edges", [&] { toond::scene::find_crease_edges(mesh); });
    if (r == 0) {
      for (auto& [name, ms] : steps) ms.clear();  // the warm-up
      std::printf("%s at n = %d: %zu vertices, %zu triangles\n", input.name.c_str(), n, mesh.positions.size(),
                  mesh.triangle_count());
    }
  }
  for (const auto& [name, ms] : steps) std::printf("%-36s %9.1f ms\n", name.c_str(), toond::bench::median(ms));
}

}  // namespace

int main(int argc, char** argv) {
  double scale = 1.0;
  int runs = 5;
  std::string only;
  std::string stages;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--scale")
      scale = std::atof(argv[i + 1]);
    else if (flag == "--runs")
      runs = std::atoi(argv[i + 1]);
    else if (flag == "--only")
      only = argv[i + 1];
    else if (flag == "--stages")
      stages = argv[i + 1];
  }
  if (!stages.empty()) {
    for (const auto& input : toond::test::heavy_inputs()) {
      if (input.name == stages) print_stages(input, static_cast<int>(input.base_n * scale), runs);
    }
    return 0;
  }
  std::printf("%-20s %9s %9s %12s %10s %10s %6s\n", "construct", "n", "MB at n", "triangles", "ms at n", "ms at 2n",
              "ratio");
  for (const auto& input : toond::test::heavy_inputs()) {
    if (!only.empty() && input.name != only) continue;
    const int n = static_cast<int>(input.base_n * scale);
    const auto m = toond::test::measure_scaling(input, n, runs);
    std::printf("%-20s %9d %9.2f %12zu %10.1f %10.1f %6.2f\n", input.name.c_str(), n, m.bytes / 1e6, m.triangles_n,
                m.seconds_n * 1e3, m.seconds_2n * 1e3, m.ratio());
    std::fflush(stdout);
  }
}
