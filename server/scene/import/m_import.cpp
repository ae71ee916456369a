#include "scene/import/m_import.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <unordered_map>
#include <vector>

#include "scene/import/bundle_import.h"
#include "scene/import/text_numbers.h"
#include "scene/reading/import_error.h"
#include "scene/reading/mesh_builder.h"
#include "text/trim.h"

namespace toond::scene {
namespace {

struct Face {
  std::size_t line = 0;
  std::int64_t id = 0;
  std::size_t first = 0;  // into Parser::face_vertex_ids_
  std::size_t count = 0;
};

class Parser {
 public:
  Parser(std::string path, std::string_view text, const ImportLimits& limits, const ImportChoices& choices)
      : path_(std::move(path)), text_(text), limits_(limits), choices_(choices) {}

  Model run() {
    parse();
    check_import_time(limits_, "parsing " + path_);
    MeshSource source = make_source();
    source.limits = limits_;
    apply_import_choices(source, choices_);
    return build_single_material_model(source, warnings_);
  }

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& what) const {
    throw ImportError(path_, path_ + ": line " + std::to_string(line) + ": " + what);
  }

  void parse() {
    std::size_t pos = 0;
    std::size_t line_number = 0;
    while (pos < text_.size()) {
      // Any of \n, \r\n and \r ends a line.
      const std::size_t end = std::min(text_.find_first_of("\r\n", pos), text_.size());
      const std::string_view line = text::trim(text_.substr(pos, end - pos));
      pos = end + ((end + 1 < text_.size() && text_[end] == '\r' && text_[end + 1] == '\n') ? 2 : 1);
      ++line_number;
      if (line.empty() || line.front() == '#') continue;
      const std::size_t brace = line.find('{');
      const std::string_view plain = line.substr(0, brace);
      std::string_view attributes;
      if (brace != std::string_view::npos) {
        const std::size_t close = line.rfind('}');
        attributes = line.substr(
            brace + 1, close == std::string_view::npos || close < brace ? std::string_view::npos : close - brace - 1);
      }
      const auto tokens = split_blanks(plain);
      if (tokens.empty()) {
        ignore("{", line_number);
      } else if (tokens[0] == "Vertex") {
        vertex(tokens, attributes, line_number);
      } else if (tokens[0] == "Face") {
        face(tokens, line_number);
      } else {
        ignore(tokens[0], line_number);
      }
    }
    if (ignored_lines_ > 0) {
      std::string kinds;
      for (const auto& [kind, count] : ignored_kinds_) {
        kinds += (kinds.empty() ? "" : ", ") + kind + " (" + std::to_string(count) + ")";
      }
      if (more_ignored_kinds_) kinds += ", ...";
      warnings_.add(path_ + ": " + std::to_string(ignored_lines_) + (ignored_lines_ == 1 ? " line" : " lines") +
                    " other than Vertex and Face " + (ignored_lines_ == 1 ? "was" : "were") + " ignored, from line " +
                    std::to_string(first_ignored_line_) + ": " + kinds);
    }
    if (bad_attributes_ > 0) {
      warnings_.add(path_ + ": " + std::to_string(bad_attributes_) + " vertex attribute" +
                    (bad_attributes_ == 1 ? " was" : "s were") + " malformed and ignored, from line " +
                    std::to_string(first_bad_attribute_line_) + " (expected normal=(x y z), uv=(u v) or rgb=(r g b))");
    }
  }

  void ignore(std::string_view kind, std::size_t line) {
    if (ignored_lines_++ == 0) first_ignored_line_ = line;
    // Only a few kinds are named: a binary file would list garbage.
    constexpr std::size_t kMaxKinds = 5;
    const std::string name(kind.substr(0, 24));
    if (ignored_kinds_.count(name) != 0 || ignored_kinds_.size() < kMaxKinds) {
      ++ignored_kinds_[name];
    } else {
      more_ignored_kinds_ = true;
    }
  }

  void bad_attribute(std::size_t line) {
    if (bad_attributes_++ == 0) first_bad_attribute_line_ = line;
  }

  void vertex(const std::vector<std::string_view>& tokens, std::string_view attributes, std::size_t line) {
    const char* form = "expected 'Vertex id x y z {attributes}' with a whole-number id and three numbers";
    if (tokens.size() != 5) fail(line, form);
    const auto id = parse_integer(tokens[1]);
    if (!id) fail(line, form);
    glm::dvec3 p;
    for (int k = 0; k < 3; ++k) {
      const auto value = parse_real(tokens[static_cast<std::size_t>(k) + 2]);
      if (!value) fail(line, form);
      p[k] = *value;
    }
    const auto index = static_cast<std::uint32_t>(positions_.size());
    if (positions_.size() >= std::numeric_limits<std::uint32_t>::max()) fail(line, "too many vertices");
    const auto [it, inserted] = index_of_id_.emplace(*id, index);
    if (!inserted) {
      fail(line, "vertex " + std::to_string(*id) + " is defined again (first on line " +
                     std::to_string(vertex_lines_[it->second]) + ")");
    }
    positions_.push_back(p);
    vertex_ids_.push_back(*id);
    vertex_lines_.push_back(line);
    normal_of_.push_back(-1);
    uv_of_.push_back(-1);
    rgb_.emplace_back(0.0);
    has_rgb_.push_back(false);
    if (!attributes.empty()) read_attributes(attributes, line);
  }

  // `key=(a b c)` or `key=value` pairs; normal, uv and rgb are kept.
  void read_attributes(std::string_view text, std::size_t line) {
    std::size_t pos = 0;
    while (pos < text.size()) {
      while (pos < text.size() && is_blank(text[pos])) ++pos;
      if (pos >= text.size()) break;
      const std::size_t key_start = pos;
      while (pos < text.size() && text[pos] != '=' && !is_blank(text[pos])) ++pos;
      const std::string_view key = text.substr(key_start, pos - key_start);
      if (pos >= text.size() || text[pos] != '=') continue;  // a bare flag
      ++pos;
      std::string_view value;
      bool parenthesised = false;
      if (pos < text.size() && text[pos] == '(') {
        const std::size_t close = text.find(')', pos);
        if (close == std::string_view::npos) {
          if (key == "normal" || key == "uv" || key == "rgb") bad_attribute(line);
          return;
        }
        value = text.substr(pos + 1, close - pos - 1);
        parenthesised = true;
        pos = close + 1;
      } else {
        const std::size_t start = pos;
        while (pos < text.size() && !is_blank(text[pos])) ++pos;
        value = text.substr(start, pos - start);
      }
      const std::size_t wanted = key == "normal" ? 3 : key == "uv" ? 2 : key == "rgb" ? 3 : 0;
      if (wanted == 0) continue;
      const auto parts = split_blanks(value);
      double numbers[3] = {0.0, 0.0, 0.0};
      bool ok = parenthesised && parts.size() == wanted;
      for (std::size_t k = 0; ok && k < wanted; ++k) {
        const auto number = parse_real(parts[k]);
        ok = number.has_value();
        if (ok) numbers[k] = *number;
      }
      if (!ok) {
        bad_attribute(line);
        continue;
      }
      const std::size_t v = positions_.size() - 1;
      if (key == "normal") {
        normal_of_[v] = static_cast<std::int64_t>(normals_.size());
        normals_.emplace_back(numbers[0], numbers[1], numbers[2]);
      } else if (key == "uv") {
        uv_of_[v] = static_cast<std::int64_t>(texcoords_.size());
        texcoords_.emplace_back(numbers[0], numbers[1]);
      } else {
        rgb_[v] = glm::dvec3(numbers[0], numbers[1], numbers[2]);
        has_rgb_[v] = true;
      }
    }
  }

  void face(const std::vector<std::string_view>& tokens, std::size_t line) {
    const char* form = "expected 'Face id v1 v2 v3 ...' with whole-number ids and at least three vertices";
    if (tokens.size() < 5) fail(line, form);
    Face f;
    f.line = line;
    const auto id = parse_integer(tokens[1]);
    if (!id) fail(line, form);
    f.id = *id;
    f.first = face_vertex_ids_.size();
    for (std::size_t k = 2; k < tokens.size(); ++k) {
      const auto vertex_id = parse_integer(tokens[k]);
      if (!vertex_id) fail(line, form);
      face_vertex_ids_.push_back(*vertex_id);
    }
    f.count = tokens.size() - 2;
    faces_.push_back(f);
  }

  MeshSource make_source() {
    MeshSource source;
    source.file = path_;
    for (const Face& f : faces_) {
      // Vertices may be listed after the faces that use them, so ids are
      // resolved once everything is read.
      std::vector<std::uint32_t> corners(f.count);
      for (std::size_t k = 0; k < f.count; ++k) {
        const std::int64_t vertex_id = face_vertex_ids_[f.first + k];
        const auto it = index_of_id_.find(vertex_id);
        if (it == index_of_id_.end()) {
          fail(f.line, "Face " + std::to_string(f.id) + " refers to vertex " + std::to_string(vertex_id) +
                           ", which no Vertex line defines");
        }
        corners[k] = it->second;
      }
      for (std::size_t k = 1; k + 1 < f.count; ++k) {
        SourceTriangle tri;
        const std::uint32_t picks[3] = {corners[0], corners[k], corners[k + 1]};
        for (int c = 0; c < 3; ++c) {
          SourceCorner& corner = tri.corner[c];
          corner.position = picks[c];
          corner.normal = normal_of_[picks[c]];
          corner.texcoord = uv_of_[picks[c]];
        }
        tri.material = 0;
        source.triangles.push_back(tri);
      }
    }
    const std::size_t with_rgb = static_cast<std::size_t>(std::count(has_rgb_.begin(), has_rgb_.end(), true));
    if (with_rgb == positions_.size() && with_rgb > 0) {
      // rgb=(r g b) as written, 0..1, sRGB-encoded like picked colours
      // (see Mesh::colors).
      source.colors = std::move(rgb_);
    } else if (with_rgb > 0) {
      warnings_.add(path_ + ": only " + std::to_string(with_rgb) + " of " + std::to_string(positions_.size()) +
                    " vertices have rgb=(...); the vertex colours were ignored");
    }
    source.positions = std::move(positions_);
    source.normals = std::move(normals_);
    source.texcoords = std::move(texcoords_);
    source.describe_position = [this](std::size_t i) {
      return "vertex " + std::to_string(vertex_ids_[i]) + " (line " + std::to_string(vertex_lines_[i]) + ")";
    };
    return source;
  }

  std::string path_;
  std::string_view text_;
  ImportLimits limits_;
  ImportChoices choices_;
  ImportWarnings warnings_;

  std::vector<glm::dvec3> positions_;
  std::vector<std::int64_t> vertex_ids_;
  std::vector<std::size_t> vertex_lines_;
  std::unordered_map<std::int64_t, std::uint32_t> index_of_id_;
  std::vector<std::int64_t> normal_of_;  // per vertex, into normals_
  std::vector<std::int64_t> uv_of_;      // per vertex, into texcoords_
  std::vector<glm::dvec3> normals_;
  std::vector<glm::dvec2> texcoords_;
  std::vector<glm::dvec3> rgb_;
  std::vector<bool> has_rgb_;

  std::vector<Face> faces_;
  std::vector<std::int64_t> face_vertex_ids_;

  std::size_t ignored_lines_ = 0;
  std::size_t first_ignored_line_ = 0;
  std::map<std::string, std::size_t> ignored_kinds_;
  bool more_ignored_kinds_ = false;
  std::size_t bad_attributes_ = 0;
  std::size_t first_bad_attribute_line_ = 0;
};

}  // namespace

Model import_m_bundle(const Bundle& bundle, const ImportLimits& limits, const ImportChoices& choices) {
  const std::string path = find_model_file(bundle, {".m"}, ".m");
  return Parser(path, *bundle.find(path), limits, choices).run();
}

}  // namespace toond::scene
