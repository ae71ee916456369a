#include "assimp_convert/scene_reading.h"

#include <map>
#include <new>
#include <string>
#include <stdexcept>

#include <assimp/IOSystem.hpp>
#include <assimp/postprocess.h>

namespace toond::assimp_convert {
namespace {

// The file system the importer sees besides the bytes it is given: empty.
class NoFiles : public Assimp::IOSystem {
 public:
  bool Exists(const char*) const override { return false; }
  char getOsSeparator() const override { return '/'; }
  Assimp::IOStream* Open(const char*, const char*) override { return nullptr; }
  void Close(Assimp::IOStream*) override {}
};

std::size_t vertices_over_four(const aiScene& scene) {
  std::size_t over = 0;
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh& mesh = *scene.mMeshes[m];
    std::map<unsigned, unsigned> influences;
    for (unsigned b = 0; b < mesh.mNumBones; ++b) {
      const aiBone& bone = *mesh.mBones[b];
      for (unsigned w = 0; w < bone.mNumWeights; ++w) {
        if (bone.mWeights[w].mWeight > 0.0f) ++influences[bone.mWeights[w].mVertexId];
      }
    }
    for (const auto& [vertex, count] : influences) over += count > 4 ? 1 : 0;
  }
  return over;
}

}  // namespace

const aiScene& read_scene(Assimp::Importer& importer, std::string_view bytes, const std::string& format) {
  importer.SetIOHandler(new NoFiles);  // the importer owns it
  // Normals a file lacks are made by the daemon, by angle; assimp's
  // validation step refuses indices past a mesh's vertices and the like.
  const unsigned steps = aiProcess_Triangulate | aiProcess_ValidateDataStructure;
  const aiScene* scene = importer.ReadFileFromMemory(bytes.data(), bytes.size(), steps, format.c_str());
  if (!scene) {
    // assimp catches its readers' exceptions, running out of memory too,
    // and keeps only their text.
    const std::string reason = importer.GetErrorString();
    if (reason.find("bad_alloc") != std::string::npos) throw std::bad_alloc();
    throw std::runtime_error(reason);
  }
  if (!scene->mRootNode) throw std::runtime_error("the file holds no scene");
  return *scene;
}

std::size_t keep_four_influences(Assimp::Importer& importer) {
  const std::size_t over = vertices_over_four(*importer.GetScene());
  if (over > 0) importer.ApplyPostProcessing(aiProcess_LimitBoneWeights);
  return over;
}

}  // namespace toond::assimp_convert
