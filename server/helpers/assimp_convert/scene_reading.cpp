#include "helpers/assimp_convert/scene_reading.h"

#include <map>
#include <new>
#include <stdexcept>
#include <string>

#include <assimp/postprocess.h>
#include <assimp/IOSystem.hpp>

#include "helpers/assimp_convert/animation_timing.h"

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

// assimp catches its readers' exceptions, running out of memory too, and
// keeps only their text.
[[noreturn]] void throw_reason(const std::string& reason) {
  if (reason.find("bad_alloc") != std::string::npos) throw std::bad_alloc();
  throw std::runtime_error(reason);
}

const aiScene& checked(const Assimp::Importer& importer) {
  const aiScene* scene = importer.GetScene();
  if (!scene || !scene->mRootNode) throw std::runtime_error("the file holds no scene");
  return *scene;
}

// A file holding a skeleton's clips and no mesh (an animation-only FBX, as
// Mixamo exports them): read without the validation that wants a mesh,
// marked incomplete as assimp marks its own animation-only scenes (BVH,
// MD5's .md5anim), and validated as one. The daemon adds its clips to the
// model beside it, or says what it holds when it came alone.
const aiScene& clips_alone(Assimp::Importer& importer, std::string_view bytes, const std::string& format,
                           const std::string& reason) {
  const aiScene* scene = importer.ReadFileFromMemory(bytes.data(), bytes.size(), 0, format.c_str());
  if (!scene || !scene->mRootNode || scene->mNumAnimations == 0) throw_reason(reason);
  // The importer keeps its scene const to its callers; it is its own,
  // made by this read.
  const_cast<aiScene*>(scene)->mFlags |= AI_SCENE_FLAGS_INCOMPLETE;
  if (!importer.ApplyPostProcessing(aiProcess_ValidateDataStructure)) throw_reason(importer.GetErrorString());
  return checked(importer);
}

}  // namespace

const aiScene& read_scene(Assimp::Importer& importer, std::string_view bytes, const std::string& format,
                          std::vector<std::string>& notes) {
  importer.SetIOHandler(new NoFiles);  // the importer owns it
  // Normals a file lacks are made by the daemon, by angle; assimp's
  // validation step refuses indices past a mesh's vertices and the like.
  const unsigned steps = aiProcess_Triangulate | aiProcess_ValidateDataStructure;
  if (importer.ReadFileFromMemory(bytes.data(), bytes.size(), steps, format.c_str())) return checked(importer);
  const std::string reason = importer.GetErrorString();
  if (reason.find("mNumMeshes is 0") != std::string::npos) return clips_alone(importer, bytes, format, reason);
  if (!timing_refusal(reason)) throw_reason(reason);
  // Refused for a clip's timing alone: everything the validation checks
  // before the clips (nodes, meshes) passed. Read again unvalidated, mend
  // the clips, and validate then.
  if (!importer.ReadFileFromMemory(bytes.data(), bytes.size(), 0, format.c_str()))
    throw_reason(importer.GetErrorString());
  // The importer keeps its scene const to its callers; it is its own,
  // made by this read, and is mended before anything else reads it.
  for (std::string& note : lengthen_clips_to_their_keys(const_cast<aiScene&>(*importer.GetScene()))) {
    notes.push_back(std::move(note));
  }
  if (!importer.ApplyPostProcessing(steps)) throw_reason(importer.GetErrorString());
  return checked(importer);
}

std::size_t keep_four_influences(Assimp::Importer& importer) {
  const std::size_t over = vertices_over_four(*importer.GetScene());
  if (over > 0) importer.ApplyPostProcessing(aiProcess_LimitBoneWeights);
  return over;
}

}  // namespace toond::assimp_convert
