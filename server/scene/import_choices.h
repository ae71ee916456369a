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
  // `?smooth_angle`: degrees at which faces of a file without normals keep
  // their own normals at a shared edge (scene/normals_by_angle.h); none:
  // kDefaultSmoothAngle. glTF is flat-shaded where normals are missing, as
  // its specification says, whatever this is.
  std::optional<double> smooth_angle;
  // `?up=z`: the file is Z-up (most CAD and 3D-printing files): turned so
  // that its +Z is toond's +Y.
  bool z_up = false;

  bool operator==(const ImportChoices&) const = default;
};

}  // namespace toond::scene
