#include "scene/import/stl_import.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "scene/import/bundle_import.h"
#include "scene/import/text_numbers.h"
#include "scene/reading/import_error.h"
#include "scene/reading/mesh_builder.h"
#include "text/trim.h"

namespace toond::scene {
namespace {

constexpr std::size_t kHeaderBytes = 80;
constexpr std::size_t kTriangleBytes = 50;  // normal, three corners (floats), attribute bytes

std::uint32_t little_u32(const unsigned char* p) {
  return static_cast<std::uint32_t>(p[0]) | static_cast<std::uint32_t>(p[1]) << 8 |
         static_cast<std::uint32_t>(p[2]) << 16 | static_cast<std::uint32_t>(p[3]) << 24;
}

float little_float(const unsigned char* p) {
  const std::uint32_t bits = little_u32(p);
  float value = 0;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

// Positions by their exact coordinates (-0 as +0), so the corners of
// neighbouring facets become one position.
class PositionTable {
 public:
  explicit PositionTable(MeshSource& source) : source_(source) {}
  std::uint32_t add(const glm::dvec3& p) {
    std::array<std::uint64_t, 3> key{};
    for (int k = 0; k < 3; ++k) {
      const double v = p[k] == 0.0 ? 0.0 : p[k];
      std::memcpy(&key[static_cast<std::size_t>(k)], &v, sizeof v);
    }
    const auto [it, inserted] = index_.try_emplace(key, static_cast<std::uint32_t>(source_.positions.size()));
    if (inserted) source_.positions.push_back(p);
    return it->second;
  }

 private:
  struct KeyHash {
    std::size_t operator()(const std::array<std::uint64_t, 3>& k) const noexcept {
      return std::hash<std::uint64_t>()(k[0] * 0x9e3779b97f4a7c15ull ^ k[1] * 0xc2b2ae3d27d4eb4full ^ k[2]);
    }
  };
  MeshSource& source_;
  std::unordered_map<std::array<std::uint64_t, 3>, std::uint32_t, KeyHash> index_;
};

void add_polygon(MeshSource& source, const std::vector<std::uint32_t>& corners) {
  for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
    SourceTriangle tri;
    tri.corner[0].position = corners[0];
    tri.corner[1].position = corners[k];
    tri.corner[2].position = corners[k + 1];
    tri.material = 0;
    source.triangles.push_back(tri);
  }
}

void check_triangle_count(const std::string& path, std::uint64_t count, const ImportLimits& limits) {
  if (count > limits.max_triangles) {
    throw ImportLimitError(path, ImportLimit::Triangles, static_cast<double>(limits.max_triangles),
                           path + " has " + std::to_string(count) + " triangles, more than");
  }
}

bool binary_size_matches(std::string_view bytes) {
  if (bytes.size() < kHeaderBytes + 4) return false;
  const std::uint64_t count = little_u32(reinterpret_cast<const unsigned char*>(bytes.data()) + kHeaderBytes);
  return bytes.size() == kHeaderBytes + 4 + count * kTriangleBytes;
}

// "solid" alone does not make ASCII: binary headers often start with it.
// ASCII STL goes on to its statements within its first lines.
constexpr std::string_view kAsciiWords[] = {"facet", "loop", "vertex", "endsolid"};
bool starts_as_ascii(std::string_view bytes) {
  const std::string_view head = text::trim(bytes.substr(0, 1024));
  const bool solid = head.starts_with("solid") &&
                     (head.size() == 5 || head[5] == ' ' || head[5] == '\t' || head[5] == '\r' || head[5] == '\n');
  return solid && std::any_of(std::begin(kAsciiWords), std::end(kAsciiWords),
                              [&](std::string_view w) { return head.find(w) != std::string_view::npos; });
}

void read_binary(const std::string& path, std::string_view bytes, const ImportLimits& limits, MeshSource& source) {
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  const std::uint32_t count = little_u32(data + kHeaderBytes);
  check_triangle_count(path, count, limits);
  PositionTable positions(source);
  source.triangles.reserve(count);
  std::vector<std::uint32_t> corners(3);
  for (std::uint32_t t = 0; t < count; ++t) {
    const unsigned char* facet = data + kHeaderBytes + 4 + static_cast<std::size_t>(t) * kTriangleBytes;
    for (int c = 0; c < 3; ++c) {
      const unsigned char* v = facet + 12 + 12 * c;  // after the facet's normal
      corners[static_cast<std::size_t>(c)] = positions.add({little_float(v), little_float(v + 4), little_float(v + 8)});
    }
    add_polygon(source, corners);
    if (t % 65536 == 65535) check_import_time(limits, "reading " + path);
  }
}

void read_ascii(const std::string& path, std::string_view text, const ImportLimits& limits, MeshSource& source) {
  PositionTable positions(source);
  std::vector<std::uint32_t> loop;
  bool in_loop = false;
  std::size_t line_number = 0;
  const auto fail = [&](const std::string& what) {
    throw ImportError(path, path + ": line " + std::to_string(line_number) + ": " + what);
  };
  for (std::size_t pos = 0; pos < text.size();) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view line = text::trim(text.substr(pos, end - pos));
    pos = end + 1;
    ++line_number;
    const std::vector<std::string_view> tokens = split_blanks(line);
    if (tokens.empty()) continue;
    const std::string_view keyword = tokens[0];
    if (keyword == "outer") {
      if (in_loop) fail("\"outer loop\" inside a loop");
      in_loop = true;
      loop.clear();
    } else if (keyword == "vertex") {
      if (!in_loop) fail("a vertex outside \"outer loop\" … \"endloop\"");
      if (tokens.size() != 4) fail("a vertex needs three coordinates");
      glm::dvec3 p;
      for (int k = 0; k < 3; ++k) {
        const auto value = parse_real(tokens[static_cast<std::size_t>(k) + 1]);
        if (!value) fail("\"" + std::string(tokens[static_cast<std::size_t>(k) + 1]) + "\" is not a number");
        p[k] = *value;
      }
      loop.push_back(positions.add(p));
    } else if (keyword == "endloop") {
      if (!in_loop) fail("\"endloop\" without \"outer loop\"");
      in_loop = false;
      add_polygon(source, loop);
      check_triangle_count(path, source.triangles.size(), limits);
    } else if (keyword != "solid" && keyword != "endsolid" && keyword != "facet" && keyword != "endfacet") {
      fail("\"" + std::string(keyword.substr(0, 40)) + "\" is not an STL statement");
    }
    if (line_number % 65536 == 0) check_import_time(limits, "reading " + path);
  }
  if (in_loop) fail("the file ends inside a loop");
}

}  // namespace

Model import_stl_bundle(const Bundle& bundle, const ImportLimits& limits, const ImportChoices& choices) {
  const std::string path = find_model_file(bundle, {".stl"}, ".stl");
  const std::string_view bytes = *bundle.find(path);
  MeshSource source;
  source.file = path;
  source.limits = limits;
  apply_import_choices(source, choices);
  if (binary_size_matches(bytes)) {
    read_binary(path, bytes, limits, source);
  } else if (starts_as_ascii(bytes)) {
    read_ascii(path, bytes, limits, source);
  } else if (bytes.size() >= kHeaderBytes + 4) {
    const std::uint64_t count = little_u32(reinterpret_cast<const unsigned char*>(bytes.data()) + kHeaderBytes);
    throw ImportError(path, path + ": a binary STL of " + std::to_string(count) + " triangles is " +
                                std::to_string(kHeaderBytes + 4 + count * kTriangleBytes) +
                                " bytes, but the file has " + std::to_string(bytes.size()) +
                                " (cut short, or the count is wrong)");
  } else {
    throw ImportError(path, path + ": " + std::to_string(bytes.size()) +
                                " bytes are too few for a binary STL (84 at least) and it is not ASCII STL");
  }
  ImportWarnings warnings;
  return build_single_material_model(source, warnings);
}

}  // namespace toond::scene
