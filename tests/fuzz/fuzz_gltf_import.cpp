// libFuzzer target: one glTF file (binary .glb or JSON .gltf, told apart by
// content) through the glTF importer, raw bytes with no record framing so
// the fuzzer mutates the container and the JSON directly. Refusals
// (ImportError) are fine; any other exception, a crash, or a mesh whose
// indices leave its vertices is a finding. Seeds: make_gltf_seeds.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "scene/bundle.h"
#include "scene/gltf_import.h"
#include "scene/import_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace toond::scene;
  Bundle bundle;
  bundle.add("model.glb", std::string(reinterpret_cast<const char*>(data), size));
  // Small limits keep each run fast, as a daemon's flags would.
  const ImportLimits limits{20000, 20000, 512 * 512};
  try {
    const Model model = import_gltf_bundle(bundle, "model.glb", limits);
    for (const auto i : model.mesh.indices) {
      if (i >= model.mesh.positions.size()) {
        std::fprintf(stderr, "fuzz_gltf_import: index out of range\n");
        std::abort();
      }
    }
  } catch (const ImportError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz_gltf_import: an exception other than ImportError: %s\n", e.what());
    std::abort();
  }
  return 0;
}
