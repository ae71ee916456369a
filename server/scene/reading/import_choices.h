#pragma once
// What an upload asks of the import besides its files. Part of the model's
// identity: the store hashes it into the id and keeps it beside the files,
// so a re-import (after a restart, or by another replica) makes the same
// model.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace toond::scene {

struct ImportChoices {
  // glTF: the scene to draw, by index; none: the file's default scene (or
  // its first).
  std::optional<int> gltf_scene;
  // `?smooth_angle`: degrees at which faces of a file without normals keep
  // their own normals at a shared edge (scene/mesh/normals_by_angle.h); none:
  // kDefaultSmoothAngle. glTF is flat-shaded where normals are missing, as
  // its specification says, whatever this is.
  std::optional<double> smooth_angle;
  // `?up`: which of the file's axes is up. Z: turned so that its +Z is
  // toond's +Y. FormatDefault: the format's convention, which import_bundle
  // and the store settle with with_format_up (bundle_import.h); an
  // importer called alone takes it as Y.
  enum class Up : std::uint8_t { FormatDefault, Y, Z };
  Up up = Up::FormatDefault;
  bool z_up() const { return up == Up::Z; }
  // `?textures`: images of the bundle put on the model's materials, as a
  // game sets a model's skins from its code: in material order, or
  // "material:image" by name; an empty entry leaves its material as the
  // file made it (scene/import/skins.h).
  std::vector<std::string> textures;

  bool operator==(const ImportChoices&) const = default;
};

}  // namespace toond::scene
