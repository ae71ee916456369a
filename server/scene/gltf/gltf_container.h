#pragma once
// The two ways a glTF 2.0 model arrives: a JSON document (.gltf) or the
// binary container (.glb) that holds the JSON and one binary chunk.
#include <optional>
#include <string>
#include <string_view>

namespace toond::scene {

// Whether `content` is a glTF model by its bytes, whatever the file is
// called: the binary container's magic "glTF", or a JSON object that names
// an "asset" (every glTF document must have one).
bool looks_like_gltf(std::string_view content);

// The JSON text of a glTF file and, for the binary container, its BIN chunk
// (views into the file's content).
struct GltfContainer {
  std::string_view json;
  std::optional<std::string_view> bin;
};

// Splits `content` (of bundle file `path`) into JSON and BIN chunk. A
// binary container whose header, chunk lengths or chunk types do not fit
// the file is an ImportError naming what is wrong; a text file is returned
// as it is (its JSON is checked by the importer).
GltfContainer open_gltf_container(std::string_view content, const std::string& path);

}  // namespace toond::scene
