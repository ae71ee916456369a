#pragma once
// What an upload asks of the import besides its files. Part of the model's
// identity: the store hashes it into the id and keeps it beside the files,
// so a re-import (after a restart, or by another replica) makes the same
// model.
#include <optional>

namespace toond::scene {

struct ImportChoices {
  // glTF: the scene to draw, by index; none: the file's default scene (or
  // its first).
  std::optional<int> gltf_scene;

  bool operator==(const ImportChoices&) const = default;
};

}  // namespace toond::scene
