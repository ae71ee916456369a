#pragma once
// glTF's binary container (.glb): a 12-byte header, a JSON chunk and at
// most one binary chunk. Written by `toon` (an OBJ bundle as one .glb) and
// by toond-assimp-convert (assimp's answer with what it leaves out added);
// the daemon reads uploads with scene/gltf/gltf_container.h, which says in
// detail what is wrong with a broken one.
#include <optional>
#include <string>
#include <string_view>

namespace toond::glb {

// The container of `json_text` (padded with spaces) and `bin` (padded with
// zeros; no binary chunk when it is empty).
std::string glb_container(std::string_view json_text, std::string_view bin);

struct GlbChunks {
  std::string_view json;
  std::string_view bin;  // empty when there is no binary chunk
};

// The chunks of `bytes`, views into it; nullopt when it is not a well-formed
// version 2 container.
std::optional<GlbChunks> glb_chunks(std::string_view bytes);

}  // namespace toond::glb
