// libFuzzer target: one glTF file (binary .glb or JSON .gltf, told apart by
// content) through the glTF importer, raw bytes with no record framing so
// the fuzzer mutates the container and the JSON directly. Refusals
// (ImportError) are fine; any other exception, a crash, or a mesh whose
// indices leave its vertices is a finding. Seeds: make_gltf_seeds. The
// input's length picks how it is read: as an uploaded file, or as the
// assimp helper's answer for a bundle that holds a texture beside it
// (GltfOrigin::Converted: image paths by file name, normals by angle).
#include <cstdio>
#include <cstdlib>
#include <string>

#include "scene/gltf/gltf_import.h"
#include "scene/reading/bundle.h"
#include "scene/reading/import_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace toond::scene;
  Bundle bundle;
  bundle.add("model.glb", std::string(reinterpret_cast<const char*>(data), size));
  const GltfOrigin origin = size % 2 == 0 ? GltfOrigin::File : GltfOrigin::Converted;
  if (origin == GltfOrigin::Converted) bundle.add("maps/skin.png", std::string("\x89PNG\r\n\x1a\n", 8));
  // Small limits keep each run fast, as a daemon's flags would.
  const ImportLimits limits{20000, 20000, 512 * 512};
  try {
    const Model model = import_gltf_bundle(bundle, "model.glb", limits, {}, origin);
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
