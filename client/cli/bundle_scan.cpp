#include "bundle_scan.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <system_error>

#include <nlohmann/json.hpp>

#include "cli_args.h"

namespace toond::cli {
namespace fs = std::filesystem;
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

char lower(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }

bool iequals(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(),
                                            [](char x, char y) { return lower(x) == lower(y); });
}

// Whether `name` ends in `suffix`, ASCII case-insensitive.
bool has_suffix(std::string_view name, std::string_view suffix) {
  return name.size() >= suffix.size() && iequals(name.substr(name.size() - suffix.size()), suffix);
}

struct Token {
  std::string text;   // with `\ ` already turned into a space
  std::size_t begin;  // offsets into the line, for rebuilding a name with spaces
  std::size_t end;
};

// Splits on unescaped white space. `\ ` is an escaped space (tinyobjloader
// and Blender write `mtllib my\ file.mtl`); any other backslash is kept, to
// be read later as a Windows path separator.
std::vector<Token> tokenize(std::string_view line) {
  std::vector<Token> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_space(line[i])) ++i;
    if (i >= line.size()) break;
    Token t{{}, i, i};
    while (i < line.size() && !is_space(line[i])) {
      if (line[i] == '\\' && i + 1 < line.size() && (line[i + 1] == ' ' || line[i + 1] == '\t')) {
        t.text += line[i + 1];
        i += 2;
      } else {
        t.text += line[i++];
      }
    }
    t.end = i;
    out.push_back(std::move(t));
  }
  return out;
}

std::string unescape_spaces(std::string_view raw) {
  std::string out;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    if (raw[i] == '\\' && i + 1 < raw.size() && (raw[i + 1] == ' ' || raw[i + 1] == '\t')) continue;
    out += raw[i];
  }
  return out;
}

bool is_number(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  errno = 0;
  std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

// How many arguments a texture option takes (the MTL spec's list plus the
// -colorspace and -texres extensions seen in the wild); -1 for -o/-s/-t,
// which take one to three numbers; 0 when `token` is no option at all.
int option_arity(std::string_view token) {
  static constexpr std::pair<std::string_view, int> kOptions[] = {
      {"-blendu", 1}, {"-blendv", 1},  {"-bm", 1},     {"-boost", 1}, {"-cc", 1},
      {"-clamp", 1},  {"-imfchan", 1}, {"-texres", 1}, {"-type", 1},  {"-colorspace", 1},
      {"-mm", 2},     {"-o", -1},      {"-s", -1},     {"-t", -1}};
  for (const auto& [name, arity] : kOptions) {
    if (iequals(token, name)) return arity;
  }
  return 0;
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
  std::size_t b = 0;
  while (b < line.size() && is_space(line[b])) ++b;
  std::size_t e = b;
  while (e < line.size() && !is_space(line[e])) ++e;
  std::size_t r = e;
  while (r < line.size() && is_space(line[r])) ++r;
  std::string_view rest = line.substr(r);
  while (!rest.empty() && is_space(rest.back())) rest.remove_suffix(1);
  return {line.substr(b, e - b), rest};
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
      throw UsageError("cannot send " + obj_path_.string() +
                       ": its name holds a quote or control character");
    }
    add(obj_name, obj_path_, *obj_text);
    if (is_gltf_name(obj_name)) {
      include_gltf_files(obj_name, *obj_text);
      return std::move(result_);
    }

    std::vector<std::size_t> mtl_indices;
    for (const std::string& line : split_lines(*obj_text)) {
      const auto [keyword, rest] = split_statement(line);
      if (!iequals(keyword, "mtllib") || rest.empty()) continue;
      for (const std::string& ref : mtllib_references(rest)) {
        if (auto index = include(obj_name, keyword, "", ref)) mtl_indices.push_back(*index);
      }
    }

    for (std::size_t index : mtl_indices) {
      // Copies, because include() grows files_ and would invalidate references.
      const std::string mtl_name = result_.files[index].name;
      const std::string mtl_text = result_.files[index].content;
      const std::string mtl_dir = parent_of(mtl_name);
      for (const std::string& line : split_lines(mtl_text)) {
        const auto [keyword, rest] = split_statement(line);
        if (!is_texture_keyword(keyword)) continue;
        const std::vector<std::string> candidates = texture_name_candidates(rest);
        if (candidates.empty()) continue;
        std::optional<Lookup> chosen;
        for (const std::string& candidate : candidates) {
          Lookup l = lookup(mtl_dir, candidate);
          if (l.kind == Lookup::found) {
            chosen = std::move(l);
            break;
          }
          if (!chosen) chosen = std::move(l);  // report on the first, fullest reading
        }
        include_lookup(mtl_name, keyword, candidates.front(), *chosen);
      }
    }
    return std::move(result_);
  }

 private:
  // A .gltf names its .bin and image files by URI (percent-encoded; data:
  // URIs carry their bytes inline); a .glb holds everything itself.
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
        include(name, "uri", "", percent_decoded(uri));
      }
    }
  }

  static std::string percent_decoded(const std::string& uri) {
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
      if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
          std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
        out.push_back(static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16)));
        i += 2;
      } else {
        out.push_back(uri[i]);
      }
    }
    return out;
  }

  // `mtllib a.mtl b.mtl` names two files, but `mtllib my model.mtl` with an
  // unescaped space names one; the disk decides which reading is meant.
  std::vector<std::string> mtllib_references(std::string_view rest) {
    std::vector<std::string> names = mtllib_names(rest);
    if (names.size() > 1) {
      const std::string whole = unescape_spaces(rest);
      if (lookup("", whole).kind == Lookup::found) return {whole};
    }
    return names;
  }

  // Looks up `ref` relative to bundle folder `from_dir` and adds the file.
  // Returns its index in the result when it was added now (not before).
  std::optional<std::size_t> include(const std::string& from, std::string_view keyword,
                                     const std::string& from_dir, const std::string& ref) {
    return include_lookup(from, keyword, ref, lookup(from_dir, ref));
  }

  std::optional<std::size_t> include_lookup(const std::string& from, std::string_view keyword,
                                            const std::string& ref, const Lookup& l) {
    const std::string what = from + ": " + std::string(keyword) + " " + in_quotes(ref);
    switch (l.kind) {
      case Lookup::missing: warn(what + " not found; not sent"); return std::nullopt;
      case Lookup::refused: warn(what + " refused: " + l.why + "; not sent"); return std::nullopt;
      case Lookup::found: break;
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

  // Resolution is lexical, as the daemon does it: `..` is applied to the
  // path as written, and may not climb above the OBJ's folder.
  Lookup lookup(const std::string& from_dir, std::string ref) const {
    std::replace(ref.begin(), ref.end(), '\\', '/');
    if (ref.empty()) return {Lookup::missing, {}, {}};
    const bool drive =
        ref.size() >= 2 && std::isalpha(static_cast<unsigned char>(ref[0])) && ref[1] == ':';
    if (ref.front() == '/' || drive) return {Lookup::refused, {}, "absolute path"};

    std::vector<std::string> segments;
    for (const std::string& part : {from_dir, ref}) {
      std::size_t start = 0;
      while (start <= part.size()) {
        std::size_t slash = part.find('/', start);
        if (slash == std::string::npos) slash = part.size();
        std::string seg = part.substr(start, slash - start);
        start = slash + 1;
        if (seg.empty() || seg == ".") continue;
        if (seg == "..") {
          if (segments.empty()) return {Lookup::refused, {}, "outside the OBJ's folder"};
          segments.pop_back();
        } else {
          segments.push_back(std::move(seg));
        }
      }
    }
    if (segments.empty()) return {Lookup::missing, {}, {}};

    // Exact name first; otherwise a case-insensitive match, because bundles
    // made on Windows or macOS often spell references in another case than
    // the files have.
    fs::path on_disk = root_;
    std::string name;
    for (const std::string& seg : segments) {
      std::error_code ec;
      std::string actual = seg;
      if (!fs::exists(fs::symlink_status(on_disk / seg, ec))) {
        std::optional<std::string> best;
        for (fs::directory_iterator it(on_disk, ec), end; !ec && it != end; it.increment(ec)) {
          const std::string entry = it->path().filename().string();
          if (iequals(entry, seg) && (!best || entry < *best)) best = entry;
        }
        if (!best) return {Lookup::missing, {}, {}};
        actual = *best;
      }
      on_disk /= actual;
      if (!name.empty()) name += '/';
      name += actual;
    }

    std::error_code ec;
    if (!fs::is_regular_file(on_disk, ec)) return {Lookup::missing, {}, {}};
    // A symbolic link inside the folder may still lead out of it.
    const fs::path real = fs::canonical(on_disk, ec);
    if (ec) return {Lookup::missing, {}, {}};
    const fs::path rel = real.lexically_relative(canonical_root_);
    if (rel.empty() || *rel.begin() == "..") {
      return {Lookup::refused, {}, "a link that leads outside the OBJ's folder"};
    }
    if (!header_safe(name)) {
      return {Lookup::refused, {}, "the name holds a quote or control character"};
    }
    return {Lookup::found, name, {}};
  }

  // The name travels in a Content-Disposition header as filename="...".
  static bool header_safe(const std::string& name) {
    return std::none_of(name.begin(), name.end(), [](char c) {
      return c == '"' || static_cast<unsigned char>(c) < 0x20 || c == 0x7f;
    });
  }

  static std::string parent_of(const std::string& bundle_path) {
    const std::size_t slash = bundle_path.rfind('/');
    return slash == std::string::npos ? std::string() : bundle_path.substr(0, slash);
  }

  fs::path obj_path_;
  fs::path root_;
  fs::path canonical_root_;
  BundleScan result_;
  std::set<std::string> sent_;
  std::set<std::string> warned_;
};

// The one model file of a folder, for `toon upload FOLDER`.
fs::path model_file_in(const fs::path& folder) {
  std::vector<fs::path> found;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file(ec) && (is_gltf_name(name) || has_suffix(name, ".obj") || has_suffix(name, ".m"))) {
      found.push_back(entry.path());
    }
  }
  if (found.size() != 1) {
    throw UsageError(folder.string() + " holds " + std::to_string(found.size()) +
                     " model files (.obj, .m, .gltf, .glb); name the one to upload");
  }
  return found.front();
}

}  // namespace

bool is_gltf_name(std::string_view name) { return has_suffix(name, ".gltf") || has_suffix(name, ".glb"); }

bool is_texture_keyword(std::string_view keyword) {
  static constexpr std::string_view kKeywords[] = {"map_Kd",   "map_Ks", "map_Ns", "map_d",
                                                   "map_Bump", "bump",   "norm",   "disp"};
  return std::any_of(std::begin(kKeywords), std::end(kKeywords),
                     [&](std::string_view k) { return iequals(k, keyword); });
}

std::vector<std::string> mtllib_names(std::string_view rest_of_line) {
  std::vector<std::string> names;
  for (Token& t : tokenize(rest_of_line)) names.push_back(std::move(t.text));
  return names;
}

std::vector<std::string> texture_name_candidates(std::string_view rest_of_line) {
  const std::vector<Token> tokens = tokenize(rest_of_line);
  std::vector<std::size_t> words;  // indices of tokens that are not options or their arguments
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const int arity = option_arity(tokens[i].text);
    if (arity > 0) {
      i += static_cast<std::size_t>(arity);
    } else if (arity < 0) {
      for (int n = 0; n < 3 && i + 1 < tokens.size() && is_number(tokens[i + 1].text); ++n) ++i;
    } else {
      words.push_back(i);
    }
  }
  if (words.empty()) return {};
  std::vector<std::string> out;
  const bool contiguous = words.back() - words.front() + 1 == words.size();
  if (words.size() > 1 && contiguous) {
    const Token& first = tokens[words.front()];
    const Token& last = tokens[words.back()];
    out.push_back(unescape_spaces(rest_of_line.substr(first.begin, last.end - first.begin)));
  }
  out.push_back(tokens[words.back()].text);
  return out;
}

BundleScan scan_obj_bundle(const fs::path& obj_path) {
  std::error_code ec;
  return Scanner(fs::is_directory(obj_path, ec) ? model_file_in(obj_path) : obj_path).run();
}

}  // namespace toond::cli
