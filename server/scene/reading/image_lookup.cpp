#include "scene/reading/image_lookup.h"

#include <array>

#include "bundle_paths/bundle_path.h"
#include "bundle_paths/model_formats.h"
#include "bundle_paths/name_index.h"

namespace toond::scene {
namespace {

// What stb_image and libwebp decode (texture_decode.h).
constexpr std::array<std::string_view, 13> kImageExtensions = {".png", ".jpg", ".jpeg", ".tga", ".bmp", ".gif", ".psd",
                                                               ".hdr", ".pic", ".pnm",  ".ppm", ".pgm", ".webp"};

std::string_view file_name_of(std::string_view path) {
  const std::size_t slash = path.find_last_of("/\\");
  return slash == std::string_view::npos ? path : path.substr(slash + 1);
}

// The file name without its last extension ("redArmor" stays as it is).
std::string_view stem_of(std::string_view file_name) {
  const std::size_t dot = file_name.rfind('.');
  return dot == std::string_view::npos || dot == 0 ? file_name : file_name.substr(0, dot);
}

// The bundle files `wanted` names, by file name or (`by_stem`) among images
// by file name less its extension, ignoring case: those beside `from` when
// there are any, else all of them.
std::vector<std::string> matching(const Bundle& bundle, std::string_view from, std::string_view wanted, bool by_stem) {
  const std::string_view folder = bundle_paths::folder_of(from);
  std::vector<std::string> beside;
  std::vector<std::string> anywhere;
  for (const std::string& path : by_stem ? bundle.paths_with_stem(wanted) : bundle.paths_named(wanted)) {
    if (by_stem && !has_image_extension(path)) continue;
    anywhere.push_back(path);
    if (bundle_paths::folder_of(path) == folder) beside.push_back(path);
  }
  return beside.empty() ? anywhere : beside;
}

}  // namespace

bool has_image_extension(std::string_view path) { return bundle_paths::has_any_extension(path, kImageExtensions); }

std::vector<std::string> bundle_images(const Bundle& bundle) {
  std::vector<std::string> images;
  for (const auto& [path, content] : bundle.files()) {
    if (has_image_extension(path)) images.push_back(path);
  }
  return images;
}

std::optional<FoundImage> find_image(const Bundle& bundle, std::string_view from, std::string_view reference) {
  if (reference.empty()) return std::nullopt;
  if (auto path = bundle.resolve(from, reference)) return FoundImage{std::move(*path), ImageMatch::Path};
  if (auto path = bundle.resolve("", reference)) return FoundImage{std::move(*path), ImageMatch::Path};
  const std::string_view name = file_name_of(reference);
  if (name.empty()) return std::nullopt;
  if (const auto found = matching(bundle, from, name, false); found.size() == 1) {
    return FoundImage{found.front(), ImageMatch::FileName};
  }
  if (const auto found = matching(bundle, from, stem_of(name), true); found.size() == 1) {
    return FoundImage{found.front(), ImageMatch::AnyFormat};
  }
  return std::nullopt;
}

std::string describe_match(const FoundImage& found) {
  switch (found.match) {
    case ImageMatch::Path:
      return "";
    case ImageMatch::FileName:
      return "was found by its file name alone, as '" + found.path + "'";
    case ImageMatch::AnyFormat:
      return "was found by its name without extension, as '" + found.path + "'";
  }
  return "";
}

}  // namespace toond::scene
