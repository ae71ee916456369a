// toond_import_bench: how long the importer takes for the same mesh as a
// binary glTF and as an OBJ. The mesh is a UV sphere made here (no shared
// model is large enough), written as OBJ text and as a GLB by the tests'
// writers; each import runs `--repeats` times, interleaved, and the medians
// are printed: the format's own importer alone, and import_bundle with the
// levels of detail and enclosure every upload also gets.
//   toond_import_bench [--segments N (default 640)] [--repeats N (default 7)]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "scene/bundle.h"
#include "scene/bundle_import.h"
#include "scene/gltf_import.h"
#include "scene/obj_import.h"
#include "support/generated_models.h"
#include "support/gltf_twin.h"

namespace {

using Clock = std::chrono::steady_clock;

template <typename F>
double seconds_of(F&& f) {
  const auto start = Clock::now();
  f();
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  int segments = 640;
  int repeats = 7;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--segments") segments = std::atoi(argv[i + 1]);
    else if (flag == "--repeats") repeats = std::atoi(argv[i + 1]);
  }
  using namespace toond;
  scene::Bundle obj;
  obj.add("sphere.obj", test::sphere_obj(segments, segments / 2));
  const scene::Model reference = scene::import_obj_bundle(obj);
  scene::Bundle glb;
  for (auto& [name, bytes] : test::write_gltf(test::gltf_twin(reference, obj), test::GltfForm::Glb)) {
    glb.add(name, std::move(bytes));
  }
  std::printf("mesh: %zu triangles; OBJ %.1f MB, GLB %.1f MB\n", reference.mesh.triangle_count(),
              obj.total_bytes() / 1e6, glb.total_bytes() / 1e6);
  std::vector<double> obj_only, glb_only, obj_full, glb_full;
  for (int r = 0; r < repeats; ++r) {
    obj_only.push_back(seconds_of([&] { scene::import_obj_bundle(obj); }));
    glb_only.push_back(seconds_of([&] { scene::import_gltf_bundle(glb, "model.glb"); }));
    obj_full.push_back(seconds_of([&] { scene::import_bundle(obj); }));
    glb_full.push_back(seconds_of([&] { scene::import_bundle(glb); }));
  }
  std::printf("median of %d      importer alone   import_bundle (with LODs)\n", repeats);
  std::printf("OBJ                %8.0f ms        %8.0f ms\n", median(obj_only) * 1e3, median(obj_full) * 1e3);
  std::printf("GLB                %8.0f ms        %8.0f ms\n", median(glb_only) * 1e3, median(glb_full) * 1e3);
  std::printf("GLB / OBJ          %8.2f           %8.2f\n", median(glb_only) / median(obj_only),
              median(glb_full) / median(obj_full));
  return 0;
}
