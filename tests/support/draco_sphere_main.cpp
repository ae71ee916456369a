// toond-test-draco-sphere OUT.glb: writes a UV sphere compressed with
// KHR_draco_mesh_compression (Draco's own encoder, through
// toond-test-draco-encode), for checks that run outside the test binaries:
// the container test uploads it to see the Draco helper work in the image.
#include <cmath>
#include <cstdio>
#include <fstream>

#include "support/gltf_draco_writer.h"
#include "support/gltf_writer.h"

namespace {

toond::test::GltfDocument sphere(int segments, int rings) {
  toond::test::GltfPrimitive primitive;
  const double pi = std::acos(-1.0);
  for (int r = 0; r <= rings; ++r) {
    const double polar = pi * r / rings;
    for (int s = 0; s <= segments; ++s) {
      const double azimuth = 2.0 * pi * s / segments;
      const glm::vec3 p(std::sin(polar) * std::cos(azimuth), std::cos(polar), std::sin(polar) * std::sin(azimuth));
      primitive.positions.push_back(p);
      primitive.normals.push_back(p);
    }
  }
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const std::uint32_t a = r * (segments + 1) + s, b = a + segments + 1;
      primitive.indices.insert(primitive.indices.end(), {a, a + 1, b, a + 1, b + 1, b});
    }
  }
  toond::test::GltfDocument document;
  document.meshes = {{primitive}};
  return document;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: toond-test-draco-sphere OUT.glb\n");
    return 2;
  }
  using namespace toond::test;
  const GltfFiles files = pack_gltf(draco_compress(build_gltf(sphere(32, 16))), GltfForm::Glb);
  std::ofstream(argv[1], std::ios::binary) << files.front().second;
  return 0;
}
