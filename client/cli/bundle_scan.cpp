#include "bundle_scan.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <system_error>

#include <nlohmann/json.hpp>

#include "bundle_paths/bundle_path.h"
#include "bundle_paths/model_formats.h"
#include "bundle_paths/name_index.h"
#include "bundle_paths/statement_names.h"
#include "cli_args.h"
#include "text/trim.h"

namespace toond::cli {
namespace fs = std::filesystem;
namespace {

// Whether `name` ends in `suffix`, ASCII case-insensitive.
bool has_suffix(std::string_view name, std::string_view suffix) {
  return name.size() >= suffix.size() &&
         bundle_paths::same_ignoring_case(name.substr(name.size() - suffix.size()), suffix);
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(std::move(line));
  }
  return lines;
}

// The first word of a line and what follows it.
std::pair<std::string_view, std::string_view> split_statement(std::string_view line) {
  line = text::trim(line);
  const std::size_t blank = line.find_first_of(" \t");
  if (blank == std::string_view::npos) return {line, {}};
  return {line.substr(0, blank), text::trim(line.substr(blank))};
}

std::optional<std::string> read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) return std::nullopt;
  return ss.str();
}

// Appending rather than "'" + ... sidesteps GCC 12's false -Wrestrict
// on string concatenation at -O3.
std::string in_quotes(std::string_view s) {
  std::string out(1, '\'');
  out.append(s).push_back('\'');
  return out;
}

// The runs of printable text in `content` (delimited by quotes, angle
// brackets, control bytes or anything outside ASCII) that end in an image
// extension, each once, in the order they first appear.
std::vector<std::string> image_names_in(std::string_view content) {
  static constexpr std::string_view kImages[] = {".png", ".jpg", ".jpeg", ".webp", ".tga", ".bmp", ".gif"};
  std::vector<std::string> names;
  std::set<std::string> seen;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= content.size(); ++i) {
    const unsigned char c = i < content.size() ? static_cast<unsigned char>(content[i]) : 0;
    if (c >= 0x20 && c < 0x7f && c != '"' && c != '<' && c != '>') continue;
    std::string_view run = content.substr(start, i - start);
    while (!run.empty() && run.front() == ' ') run.remove_prefix(1);
    if (!run.empty() && run.size() < 1024 && bundle_paths::has_any_extension(run, kImages) &&
        seen.insert(std::string(run)).second) {
      names.emplace_back(run);
    }
    start = i + 1;
  }
  return names;
}

// The outcome of looking up one reference.
struct Lookup {
  enum Kind { found, missing, refused } kind;
  std::string name;  // found: the bundle path with the case found on disk
  std::string why;   // refused: the reason
};

class Scanner {
 public:
  explicit Scanner(const fs::path& obj_path) : obj_path_(obj_path) {
    root_ = obj_path.parent_path();
    if (root_.empty()) root_ = ".";
    std::error_code ec;
    canonical_root_ = fs::canonical(root_, ec);
    if (ec) canonical_root_ = fs::absolute(root_, ec).lexically_normal();
  }

  BundleScan run() {
    std::error_code ec;
    if (!fs::is_regular_file(obj_path_, ec)) {
      throw UsageError("cannot read " + obj_path_.string() + ": " +
                       (fs::exists(obj_path_, ec) ? "not a regular file" : "no such file"));
    }
    std::optional<std::string> obj_text = read_file(obj_path_);
    if (!obj_text) {
      throw UsageError("cannot read " + obj_path_.string() + ": " + std::strerror(errno));
    }
    const std::string obj_name = obj_path_.filename().string();
    if (!header_safe(obj_name)) {
      throw UsageError("cannot send " + obj_path_.string() + ": its name holds a quote or control character");
    }
    add(obj_name, obj_path_, *obj_text);
    if (is_gltf_name(obj_name)) {
      include_gltf_files(obj_name, *obj_text);
      return std::move(result_);
    }
    // STL and PLY name no other files.
    if (has_suffix(obj_name, ".stl") || has_suffix(obj_name, ".ply")) return std::move(result_);
    if (bundle_paths::has_any_extension(obj_name, bundle_paths::assimp_model_extensions())) {
      include_named_images(obj_name, *obj_text);
      return std::move(result_);
    }

    std::vector<std::size_t> mtl_indices;
    for (const std::string& line : split_lines(*obj_text)) {
      const auto [keyword, rest] = split_statement(line);
      if (!bundle_paths::same_ignoring_case(keyword, "mtllib") || rest.empty()) continue;
      const auto exists = [&](const std::string& name) { return lookup(obj_name, name).kind == Lookup::found; };
      for (const std::string& ref : bundle_paths::mtllib_names(rest, exists)) {
        if (auto index = include(obj_name, keyword, ref)) mtl_indices.push_back(*index);
      }
    }

    for (std::size_t index : mtl_indices) {
      // Copies, because include() grows files_ and would invalidate references.
      const std::string mtl_name = result_.files[index].name;
      const std::string mtl_text = result_.files[index].content;
      for (const std::string& line : split_lines(mtl_text)) {
        const auto [keyword, rest] = split_statement(line);
        if (!is_texture_keyword(keyword)) continue;
        include_first_found(mtl_name, keyword, bundle_paths::texture_names(rest));
      }
    }
    return std::move(result_);
  }

 private:
  // A .gltf names its .bin and image files by URI (data: URIs carry their
  // bytes inline); a .glb holds everything itself.
  void include_gltf_files(const std::string& name, const std::string& text) {
    const nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
    if (!doc.is_object()) return;  // a .glb, or JSON the daemon will explain
    for (const char* list : {"buffers", "images"}) {
      const auto it = doc.find(list);
      if (it == doc.end() || !it->is_array()) continue;
      for (const nlohmann::json& item : *it) {
        if (!item.is_object() || !item.contains("uri") || !item["uri"].is_string()) continue;
        const std::string uri = item["uri"].get<std::string>();
        if (uri.rfind("data:", 0) == 0) continue;
        include(name, "uri", bundle_paths::uri_reference(uri));
      }
    }
  }

  // FBX, COLLADA, 3DS and the other formats read through assimp name their
  // textures by path inside the file (binary or text), often the artist's
  // absolute one: every run of text in it that ends in an image file's
  // extension is looked up as the daemon does, as written and then by its
  // file name alone beside the model.
  void include_named_images(const std::string& name, const std::string& content) {
    for (const std::string& written : image_names_in(content)) {
      include_first_found(name, "texture", bundle_paths::path_names(written));
    }
  }

  // Adds the first of `candidates` (the readings of one reference, fullest
  // first) found beside `from`; reports on the first when none is.
  void include_first_found(const std::string& from, std::string_view keyword,
                           const std::vector<bundle_paths::TextureName>& candidates) {
    if (candidates.empty()) return;
    std::optional<Lookup> chosen;
    for (const bundle_paths::TextureName& candidate : candidates) {
      Lookup l = lookup(from, candidate.name);
      if (l.kind == Lookup::found) {
        chosen = std::move(l);
        break;
      }
      if (!chosen) chosen = std::move(l);  // report on the first, fullest reading
    }
    include_lookup(from, keyword, candidates.front().name, *chosen);
  }

  // Looks up `ref` relative to bundle file `from` and adds the file.
  // Returns its index in the result when it was added now (not before).
  std::optional<std::size_t> include(const std::string& from, std::string_view keyword, const std::string& ref) {
    return include_lookup(from, keyword, ref, lookup(from, ref));
  }

  std::optional<std::size_t> include_lookup(const std::string& from, std::string_view keyword, const std::string& ref,
                                            const Lookup& l) {
    const std::string what = from + ": " + std::string(keyword) + " " + in_quotes(ref);
    switch (l.kind) {
      case Lookup::missing:
        warn(what + " not found; not sent");
        return std::nullopt;
      case Lookup::refused:
        warn(what + " refused: " + l.why + "; not sent");
        return std::nullopt;
      case Lookup::found:
        break;
    }
    if (sent_.count(l.name)) return std::nullopt;
    std::optional<std::string> content = read_file(root_ / fs::path(l.name));
    if (!content) {
      warn(what + " cannot be read (" + std::strerror(errno) + "); not sent");
      return std::nullopt;
    }
    add(l.name, root_ / fs::path(l.name), std::move(*content));
    return result_.files.size() - 1;
  }

  // Several materials of one MTL often name the same missing texture; once
  // is enough.
  void warn(std::string message) {
    if (warned_.insert(message).second) result_.warnings.push_back(std::move(message));
  }

  void add(const std::string& name, const fs::path& disk, std::string content) {
    sent_.insert(name);
    result_.files.push_back(BundleFile{name, disk, std::move(content)});
  }

  // The daemon's rule, so that what is sent is what it will look for: the
  // reference is read by bundle_paths::resolve_reference (lexically: `..`
  // never climbs above the OBJ's folder) and matched to a file by NameIndex.
  Lookup lookup(const std::string& from, const std::string& ref) const {
    const bundle_paths::Reading reading = bundle_paths::resolve_reference(from, ref);
    switch (reading.refusal) {
      case bundle_paths::Refusal::none:
        break;
      case bundle_paths::Refusal::empty:
        return {Lookup::missing, {}, {}};
      case bundle_paths::Refusal::absolute:
        return {Lookup::refused, {}, "absolute path"};
      case bundle_paths::Refusal::outside:
        return {Lookup::refused, {}, "outside the OBJ's folder"};
      case bundle_paths::Refusal::malformed:
        return {Lookup::refused, {}, "a NUL byte or a name too long to store"};
    }
    const std::optional<std::string> name = file_named(reading.path);
    if (!name) return {Lookup::missing, {}, {}};

    std::error_code ec;
    // A symbolic link inside the folder may still lead out of it.
    const fs::path real = fs::canonical(root_ / fs::path(*name), ec);
    if (ec) return {Lookup::missing, {}, {}};
    const fs::path rel = real.lexically_relative(canonical_root_);
    if (rel.empty() || *rel.begin() == "..") {
      return {Lookup::refused, {}, "a link that leads outside the OBJ's folder"};
    }
    // The daemon would refuse the whole upload for such a name.
    if (const auto why = bundle_paths::unprintable_reason(*name)) {
      return {Lookup::refused, {}, "the name holds " + *why};
    }
    if (!header_safe(*name)) {
      return {Lookup::refused, {}, "the name holds a quote or control character"};
    }
    return {Lookup::found, *name, {}};
  }

  // The regular file under the OBJ's folder that bundle path `path` names:
  // the path as written, else whichever spelling on disk NameIndex picks
  // among those that differ from it only in case.
  std::optional<std::string> file_named(const std::string& path) const {
    std::error_code ec;
    if (fs::is_regular_file(root_ / fs::path(path), ec)) return path;
    std::vector<std::string> spellings{""};
    for (std::size_t start = 0; start <= path.size() && !spellings.empty();) {
      const std::size_t slash = std::min(path.find('/', start), path.size());
      const std::string wanted = bundle_paths::case_folded(path.substr(start, slash - start));
      start = slash + 1;
      std::vector<std::string> longer;
      for (const std::string& prefix : spellings) {
        for (fs::directory_iterator it(root_ / fs::path(prefix), ec), end; !ec && it != end; it.increment(ec)) {
          const std::string entry = it->path().filename().string();
          if (bundle_paths::case_folded(entry) == wanted)
            longer.push_back(prefix.empty() ? entry : prefix + '/' + entry);
        }
        ec.clear();
      }
      spellings = std::move(longer);
    }
    bundle_paths::NameIndex files;
    for (const std::string& spelling : spellings) {
      if (fs::is_regular_file(root_ / fs::path(spelling), ec)) files.add(spelling);
    }
    return files.find(path);
  }

  // The name travels in a Content-Disposition header as filename="...".
  static bool header_safe(const std::string& name) {
    return std::none_of(name.begin(), name.end(),
                        [](char c) { return c == '"' || static_cast<unsigned char>(c) < 0x20 || c == 0x7f; });
  }

  fs::path obj_path_;
  fs::path root_;
  fs::path canonical_root_;
  BundleScan result_;
  std::set<std::string> sent_;
  std::set<std::string> warned_;
};

// The model files of a folder (not its subfolders), in name order.
std::vector<fs::path> model_files_in(const fs::path& folder) {
  std::vector<fs::path> found;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file(ec) && bundle_paths::is_model_file(name)) found.push_back(entry.path());
  }
  std::sort(found.begin(), found.end());
  if (found.empty()) {
    throw UsageError(folder.string() + " holds no model file (" + std::string(bundle_paths::kModelFormatsText) + ")");
  }
  return found;
}

// Whether a file beside the model travels with a folder's upload: images
// (a game's skins, which its model files often do not name) and Quake's
// .skin files.
bool sent_with_folder(const std::string& name) {
  static constexpr std::string_view kBeside[] = {".png", ".jpg", ".jpeg", ".webp", ".tga",
                                                 ".bmp", ".gif", ".psd",  ".skin"};
  return bundle_paths::has_any_extension(name, kBeside);
}

// `toon upload FOLDER`: each model file of the folder with the files it
// names (the daemon tells the model from the files holding its clips
// alone, and says so when it cannot), and every image beside them.
BundleScan scan_folder(const fs::path& folder) {
  BundleScan scan;
  std::set<std::string> sent;
  const auto merge = [&](BundleScan part) {
    for (BundleFile& file : part.files) {
      if (sent.insert(file.name).second) scan.files.push_back(std::move(file));
    }
    for (std::string& warning : part.warnings) scan.warnings.push_back(std::move(warning));
  };
  for (const fs::path& model : model_files_in(folder)) merge(Scanner(model).run());
  std::vector<fs::path> beside;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    if (entry.is_regular_file(ec) && sent_with_folder(entry.path().filename().string())) beside.push_back(entry.path());
  }
  std::sort(beside.begin(), beside.end());
  for (const fs::path& path : beside) {
    const std::string name = path.filename().string();
    if (sent.count(name) != 0) continue;
    if (std::any_of(name.begin(), name.end(),
                    [](char c) { return c == '"' || static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }) ||
        bundle_paths::unprintable_reason(name)) {
      scan.warnings.push_back(path.string() + ": its name cannot be sent; not sent");
      continue;
    }
    std::optional<std::string> content = read_file(path);
    if (!content) {
      scan.warnings.push_back(path.string() + " cannot be read (" + std::strerror(errno) + "); not sent");
      continue;
    }
    sent.insert(name);
    scan.files.push_back(BundleFile{name, path, std::move(*content)});
  }
  return scan;
}

}  // namespace

bool is_gltf_name(std::string_view name) { return has_suffix(name, ".gltf") || has_suffix(name, ".glb"); }

bool is_texture_keyword(std::string_view keyword) {
  static constexpr std::string_view kKeywords[] = {"map_Kd",   "map_Ks", "map_Ns", "map_d",
                                                   "map_Bump", "bump",   "norm",   "disp"};
  return std::any_of(std::begin(kKeywords), std::end(kKeywords),
                     [&](std::string_view k) { return bundle_paths::same_ignoring_case(k, keyword); });
}

BundleScan scan_obj_bundle(const fs::path& obj_path) {
  std::error_code ec;
  return fs::is_directory(obj_path, ec) ? scan_folder(obj_path) : Scanner(obj_path).run();
}

}  // namespace toond::cli
