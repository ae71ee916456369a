#pragma once
// The image a model file names, found in an upload as games find theirs:
// Quake-family files name textures without an extension and in another
// case (`models/powerups/armor/redArmor` for `redarmor.tga`), tools write
// the artist's absolute path (`/home/.../lower.png` for a `lower.jpg`
// shipped beside the model), and a pack's paths start at the game's root.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/reading/bundle.h"

namespace toond::scene {

// How an image was found, for the warning that says so.
enum class ImageMatch {
  Path,       // the path as written (relative to the naming file, or to the bundle's root), any case
  FileName,   // its file name alone: beside the naming file, else the one such file of the bundle
  AnyFormat,  // its name without extension, with any image extension the bundle has
};

struct FoundImage {
  std::string path;  // the bundle path
  ImageMatch match = ImageMatch::Path;
};

// The bundle image `reference` (as bundle file `from` writes it) names, in
// this order: the path (case-insensitively, bundle_paths::NameIndex), the
// same path from the bundle's root, the file name alone beside `from`, the
// one bundle file of that name anywhere, and then the same three by the
// name without its extension among the bundle's images (PNG, JPEG, TGA,
// BMP, ...). A name that several files anywhere match but none beside
// `from` finds none: guessing could draw the wrong skin.
std::optional<FoundImage> find_image(const Bundle& bundle, std::string_view from, std::string_view reference);

// Whether bundle path `path` ends in an image extension toond decodes.
bool has_image_extension(std::string_view path);

// The bundle's image files (by extension), in path order.
std::vector<std::string> bundle_images(const Bundle& bundle);

// The words a warning gives a match found by other than its path: "was
// found by its file name alone, as 'x.png'" and the like; empty for Path.
std::string describe_match(const FoundImage& found);

}  // namespace toond::scene
