#pragma once
// Clips from a file beside the mesh: a file holding a skeleton's animation
// alone (an .md5anim, a BVH, the animation-only FBX or glTF files Mixamo and
// others export for one character) added to the model's glTF, channel by
// channel onto the model's nodes of the same name. A clip one of whose
// channels names a node the model lacks is left out, with a warning naming
// the joints. Both files are glTF here: the model as uploaded or converted,
// the clip file the same way.
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace toond::scene {

// The bytes of a buffer a glTF file names by URI (relative to the file), or
// nullopt when it cannot be had.
using BufferFiles = std::function<std::optional<std::string>(const std::string& uri)>;

struct MergedClips {
  std::string gltf;  // the model's glTF, binary, with the clips added
  // For each clip added, in order after the model's own: its index among
  // the clip file's animations.
  std::vector<std::size_t> added;
};

// `model` (a glTF or GLB file's bytes) with the animations of `clips`
// added; `clips_path` names the clip file in warnings, `clip_buffers`
// serves its external buffers. Warnings for clips left out go to
// `warnings`. Throws ImportError naming `clips_path` when it is not glTF.
MergedClips merge_clips(std::string_view model, const std::string& model_path, std::string_view clips,
                        const std::string& clips_path, const BufferFiles& clip_buffers,
                        std::vector<std::string>& warnings);

// What a glTF file holds, read from its JSON alone: whether it has meshes,
// its animations' names and how many nodes they move. nullopt when it is not
// readable glTF.
struct GltfContents {
  bool meshes = false;
  std::vector<std::string> clips;
  std::size_t nodes = 0;
};
std::optional<GltfContents> gltf_contents(std::string_view bytes);

}  // namespace toond::scene
