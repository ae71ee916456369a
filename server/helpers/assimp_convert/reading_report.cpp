#include "helpers/assimp_convert/reading_report.h"

namespace toond::assimp_convert {
namespace {

std::string counted(std::size_t n, const std::string& one, const std::string& many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

std::vector<std::string> not_carried(const aiScene& scene, std::size_t vertices_over_four_influences) {
  std::vector<std::string> said;
  if (scene.mNumCameras > 0) said.push_back(counted(scene.mNumCameras, "camera", "cameras") + " not read");
  if (scene.mNumLights > 0) said.push_back(counted(scene.mNumLights, "light", "lights") + " not read");
  if (vertices_over_four_influences > 0) {
    said.push_back(counted(vertices_over_four_influences, "vertex follows", "vertices follow") +
                   " more than four joints; each keeps its four strongest, renormalised");
  }
  std::size_t extra_colour_sets = 0;
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const unsigned colour_sets = scene.mMeshes[m]->GetNumColorChannels();
    extra_colour_sets += colour_sets > 1 ? colour_sets - 1 : 0;
  }
  if (extra_colour_sets > 0) {
    said.push_back(counted(extra_colour_sets, "vertex colour set", "vertex colour sets") +
                   " past each mesh's first not read");
  }
  return said;
}

}  // namespace toond::assimp_convert
