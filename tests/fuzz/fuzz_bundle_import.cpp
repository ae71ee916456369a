// libFuzzer target: a bundle (OBJ or .m, MTL, textures, IQM with clip files) through the importer
// the daemon runs on every upload. Refusals (ImportError) are fine; any other
// exception, a crash, or a mesh with NaN/Inf or an index out of range (what
// would reach the GPU) is a finding.
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "fuzz_input.h"
#include "scene/import/bundle_import.h"
#include "scene/reading/bundle.h"
#include "scene/reading/import_error.h"

namespace {

[[noreturn]] void finding(const char* what) {
  std::fprintf(stderr, "fuzz_bundle_import: %s\n", what);
  std::abort();
}

bool finite(const auto& v) {
  for (int i = 0; i < v.length(); ++i) {
    if (!std::isfinite(v[i])) return false;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace toond::scene;
  Bundle bundle;
  try {
    for (auto& [name, content] : toond::fuzz::split_files(data, size)) bundle.add(name, std::move(content));
  } catch (const ImportError&) {
    return 0;
  }
  // Small limits keep each run fast, as a daemon's flags would.
  const ImportLimits limits{20000, 20000, 512 * 512};
  Model model;
  try {
    model = import_bundle(bundle, limits);
  } catch (const ImportError&) {
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "unexpected exception: %s\n", e.what());
    finding("an exception other than ImportError (a 500 in the daemon)");
  }
  const Mesh& mesh = model.mesh;
  if (mesh.indices.empty() || mesh.indices.size() % 3 != 0) finding("no whole triangles");
  if (model.materials.empty()) finding("no material");
  const std::size_t n = mesh.positions.size();
  if (mesh.normals.size() != n || mesh.outline_normals.size() != n || mesh.texcoords.size() != n ||
      mesh.tangents.size() != n || (!mesh.colors.empty() && mesh.colors.size() != n)) {
    finding("vertex streams of different lengths");
  }
  for (const auto i : mesh.indices) {
    if (i >= n) finding("index out of range");
  }
  for (std::size_t v = 0; v < n; ++v) {
    if (!finite(mesh.positions[v]) || !finite(mesh.normals[v]) || !finite(mesh.outline_normals[v]) ||
        !finite(mesh.texcoords[v]) || !finite(mesh.tangents[v])) {
      finding("a vertex value that is not finite would reach the GPU");
    }
  }
  for (const auto& sub : mesh.submeshes) {
    if (sub.first_index + sub.index_count > mesh.indices.size()) finding("submesh past the indices");
    if (sub.material < 0 || static_cast<std::size_t>(sub.material) >= model.materials.size()) {
      finding("submesh material out of range");
    }
  }
  for (const auto& m : model.materials) {
    if ((m.diffuse_texture >= 0 && static_cast<std::size_t>(m.diffuse_texture) >= model.textures.size()) ||
        (m.normal_texture >= 0 && static_cast<std::size_t>(m.normal_texture) >= model.textures.size())) {
      finding("material texture out of range");
    }
  }
  for (const auto& t : model.textures) {
    if (t.rgba.size() != static_cast<std::size_t>(t.width) * static_cast<std::size_t>(t.height) * 4) {
      finding("texture size and pixels disagree");
    }
  }
  return 0;
}
