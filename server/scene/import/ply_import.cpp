#include "scene/import/ply_import.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/import/bundle_import.h"
#include "scene/import/text_numbers.h"
#include "scene/reading/import_error.h"
#include "scene/reading/mesh_builder.h"
#include "text/trim.h"

namespace toond::scene {
namespace {

constexpr std::size_t kMaxHeaderBytes = 64 * 1024;

enum class Format { Ascii, BinaryLittle, BinaryBig };

enum class Type { Int8, Uint8, Int16, Uint16, Int32, Uint32, Float32, Float64 };

std::optional<Type> type_named(std::string_view name) {
  if (name == "char" || name == "int8") return Type::Int8;
  if (name == "uchar" || name == "uint8") return Type::Uint8;
  if (name == "short" || name == "int16") return Type::Int16;
  if (name == "ushort" || name == "uint16") return Type::Uint16;
  if (name == "int" || name == "int32") return Type::Int32;
  if (name == "uint" || name == "uint32") return Type::Uint32;
  if (name == "float" || name == "float32") return Type::Float32;
  if (name == "double" || name == "float64") return Type::Float64;
  return std::nullopt;
}

std::size_t size_of(Type t) {
  switch (t) {
    case Type::Int8:
    case Type::Uint8:
      return 1;
    case Type::Int16:
    case Type::Uint16:
      return 2;
    case Type::Int32:
    case Type::Uint32:
    case Type::Float32:
      return 4;
    case Type::Float64:
      return 8;
  }
  return 1;
}

struct Property {
  std::string name;
  Type type = Type::Float32;
  std::optional<Type> list_count;  // set: a list, `type` its items' type
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
};

struct Header {
  Format format = Format::Ascii;
  std::vector<Element> elements;
  std::size_t data_start = 0;  // the byte after "end_header\n"
};

class Failure {
 public:
  explicit Failure(std::string path) : path_(std::move(path)) {}
  [[noreturn]] void operator()(const std::string& what) const { throw ImportError(path_, path_ + ": " + what); }

 private:
  std::string path_;
};

Header read_header(std::string_view bytes, const Failure& fail) {
  const std::size_t end = bytes.find("end_header");
  if (end > kMaxHeaderBytes) {  // npos too
    fail(end == std::string_view::npos ? "no end_header: not a PLY file, or cut short in its header"
                                       : "a header over 64 KiB");
  }
  const std::size_t newline = bytes.find('\n', end);
  Header header;
  header.data_start = newline == std::string_view::npos ? bytes.size() : newline + 1;
  const std::string_view text = bytes.substr(0, end);
  bool magic = false, format = false;
  for (std::size_t pos = 0; pos < text.size();) {
    const std::size_t line_end = std::min(text.find('\n', pos), text.size());
    const std::vector<std::string_view> t = split_blanks(text::trim(text.substr(pos, line_end - pos)));
    pos = line_end + 1;
    if (t.empty()) continue;
    if (!magic) {
      if (t[0] != "ply") fail("does not start with \"ply\"");
      magic = true;
    } else if (t[0] == "format") {
      if (t.size() < 2) fail("a format line without a format");
      if (t[1] == "ascii")
        header.format = Format::Ascii;
      else if (t[1] == "binary_little_endian")
        header.format = Format::BinaryLittle;
      else if (t[1] == "binary_big_endian")
        header.format = Format::BinaryBig;
      else
        fail("unknown format \"" + std::string(t[1].substr(0, 40)) + "\"");
      format = true;
    } else if (t[0] == "element") {
      const auto count = t.size() == 3 ? parse_integer(t[2]) : std::nullopt;
      if (!count || *count < 0) fail("an element line needs a name and a count");
      header.elements.push_back({std::string(t[1].substr(0, 64)), static_cast<std::uint64_t>(*count), {}});
    } else if (t[0] == "property") {
      if (header.elements.empty()) fail("a property before any element");
      Property p;
      if (t.size() == 5 && t[1] == "list") {
        p.list_count = type_named(t[2]);
        const auto item = type_named(t[3]);
        if (!p.list_count || !item) fail("a list property of an unknown type");
        p.type = *item;
        p.name = std::string(t[4].substr(0, 64));
      } else if (t.size() == 3) {
        const auto type = type_named(t[1]);
        if (!type) fail("unknown property type \"" + std::string(t[1].substr(0, 40)) + "\"");
        p.type = *type;
        p.name = std::string(t[2].substr(0, 64));
      } else {
        fail("a property line needs a type and a name");
      }
      header.elements.back().properties.push_back(std::move(p));
    } else if (t[0] != "comment" && t[0] != "obj_info") {
      fail("\"" + std::string(t[0].substr(0, 40)) + "\" is not a PLY header statement");
    }
  }
  if (!format) fail("no format line in the header");
  return header;
}

// Reads the values of the data section one after another, as text tokens
// or as bytes in the file's order.
class ValueReader {
 public:
  ValueReader(std::string_view data, Format format, const Failure& fail) : data_(data), format_(format), fail_(fail) {}

  double next(Type type) { return format_ == Format::Ascii ? next_token() : next_binary(type); }
  std::size_t bytes_left() const { return data_.size() - pos_; }

 private:
  double next_token() {
    while (pos_ < data_.size() && std::isspace(static_cast<unsigned char>(data_[pos_]))) ++pos_;
    const std::size_t start = pos_;
    while (pos_ < data_.size() && !std::isspace(static_cast<unsigned char>(data_[pos_]))) ++pos_;
    if (pos_ == start) fail_("the data ends before the header's counts are read");
    const auto value = parse_real(data_.substr(start, pos_ - start));
    if (!value)
      fail_("\"" + std::string(data_.substr(start, std::min<std::size_t>(pos_ - start, 40))) + "\" is not a number");
    return *value;
  }

  double next_binary(Type type) {
    const std::size_t n = size_of(type);
    if (data_.size() - pos_ < n) fail_("the data ends before the header's counts are read");
    unsigned char b[8];
    std::memcpy(b, data_.data() + pos_, n);
    pos_ += n;
    const bool little = format_ == Format::BinaryLittle;
    std::uint64_t bits = 0;
    for (std::size_t i = 0; i < n; ++i) bits |= static_cast<std::uint64_t>(b[little ? i : n - 1 - i]) << (8 * i);
    switch (type) {
      case Type::Int8:
        return static_cast<std::int8_t>(bits);
      case Type::Uint8:
        return static_cast<std::uint8_t>(bits);
      case Type::Int16:
        return static_cast<std::int16_t>(bits);
      case Type::Uint16:
        return static_cast<std::uint16_t>(bits);
      case Type::Int32:
        return static_cast<std::int32_t>(bits);
      case Type::Uint32:
        return static_cast<std::uint32_t>(bits);
      case Type::Float32: {
        const auto u = static_cast<std::uint32_t>(bits);
        float f = 0;
        std::memcpy(&f, &u, sizeof f);
        return f;
      }
      case Type::Float64: {
        double d = 0;
        std::memcpy(&d, &bits, sizeof d);
        return d;
      }
    }
    return 0;
  }

  std::string_view data_;
  Format format_;
  const Failure& fail_;
  std::size_t pos_ = 0;
};

// Where the vertex element keeps what toond reads (indices into its
// properties).
struct VertexLayout {
  std::optional<std::size_t> x, y, z, nx, ny, nz, u, v, red, green, blue;
  bool colour_bytes = false;
};

VertexLayout vertex_layout(const Element& e) {
  VertexLayout l;
  for (std::size_t i = 0; i < e.properties.size(); ++i) {
    const std::string& n = e.properties[i].name;
    if (e.properties[i].list_count) continue;
    if (n == "x")
      l.x = i;
    else if (n == "y")
      l.y = i;
    else if (n == "z")
      l.z = i;
    else if (n == "nx")
      l.nx = i;
    else if (n == "ny")
      l.ny = i;
    else if (n == "nz")
      l.nz = i;
    else if (n == "s" || n == "u" || n == "texture_u" || n == "texture_s")
      l.u = i;
    else if (n == "t" || n == "v" || n == "texture_v" || n == "texture_t")
      l.v = i;
    else if (n == "red" || n == "diffuse_red")
      l.red = i;
    else if (n == "green" || n == "diffuse_green")
      l.green = i;
    else if (n == "blue" || n == "diffuse_blue")
      l.blue = i;
  }
  if (l.red) {
    const Type t = e.properties[*l.red].type;
    l.colour_bytes = t != Type::Float32 && t != Type::Float64;
  }
  return l;
}

class PlyReader {
 public:
  PlyReader(std::string path, std::string_view bytes, const ImportLimits& limits, ImportWarnings& warnings)
      : path_(std::move(path)), bytes_(bytes), limits_(limits), warnings_(warnings), fail_(path_) {}

  MeshSource read() {
    const Header header = read_header(bytes_, fail_);
    check_counts(header);
    ValueReader values(bytes_.substr(header.data_start), header.format, fail_);
    MeshSource source;
    source.file = path_;
    source.limits = limits_;
    for (const Element& e : header.elements) {
      if (e.name == "vertex")
        read_vertices(e, values, source);
      else if (e.name == "face")
        read_faces(e, values, source);
      else
        skip(e, values);
    }
    if (!colours_.empty()) source.colors = std::move(colours_);
    return source;
  }

 private:
  void check_counts(const Header& header) const {
    // Every instance takes a byte at least (a token and a space in ASCII),
    // so a count the rest of the file cannot hold is a lie, told before
    // anything is allocated for it.
    const std::uint64_t left = bytes_.size() - std::min(header.data_start, bytes_.size());
    for (const Element& e : header.elements) {
      if (e.count > left) {
        fail_("element \"" + e.name + "\" claims " + std::to_string(e.count) + " entries, more than the " +
              std::to_string(left) + " bytes after the header can hold");
      }
      if (e.name == "vertex" && e.count > limits_.max_vertices) {
        throw ImportLimitError(path_, ImportLimit::Vertices, static_cast<double>(limits_.max_vertices),
                               path_ + " has " + std::to_string(e.count) + " vertex positions, more than");
      }
      if (e.name == "face" && e.count > limits_.max_triangles) {
        throw ImportLimitError(path_, ImportLimit::Triangles, static_cast<double>(limits_.max_triangles),
                               path_ + " has " + std::to_string(e.count) + " faces, more than");
      }
    }
  }

  // The upload answer says what of the file was left out.
  void warn_unread(const Element& e, const std::vector<std::string>& read) {
    std::string unread;
    for (const Property& p : e.properties) {
      if (std::find(read.begin(), read.end(), p.name) == read.end()) unread += (unread.empty() ? "" : ", ") + p.name;
    }
    if (!unread.empty()) warnings_.add(path_ + ": " + e.name + " properties not read: " + unread);
  }

  void read_vertices(const Element& e, ValueReader& values, MeshSource& source) {
    const VertexLayout l = vertex_layout(e);
    std::vector<std::string> read;
    for (const auto& at : {l.x, l.y, l.z, l.nx, l.ny, l.nz, l.u, l.v, l.red, l.green, l.blue}) {
      if (at) read.push_back(e.properties[*at].name);
    }
    warn_unread(e, read);
    if (!l.x || !l.y || !l.z) fail_("the vertex element has no x, y and z");
    const bool normals = l.nx && l.ny && l.nz;
    const bool uvs = l.u && l.v;
    const bool colours = l.red && l.green && l.blue;
    std::vector<double> row(e.properties.size());
    for (std::uint64_t i = 0; i < e.count; ++i) {
      read_row(e, values, row);
      source.positions.emplace_back(row[*l.x], row[*l.y], row[*l.z]);
      if (normals) source.normals.emplace_back(row[*l.nx], row[*l.ny], row[*l.nz]);
      // PLY's v runs up the image, as OBJ's does.
      if (uvs) source.texcoords.emplace_back(row[*l.u], row[*l.v]);
      if (colours) {
        const double scale = l.colour_bytes ? 1.0 / 255.0 : 1.0;
        colours_.emplace_back(row[*l.red] * scale, row[*l.green] * scale, row[*l.blue] * scale);
      }
      if (i % 65536 == 65535) check_import_time(limits_, "reading " + path_);
    }
    has_normals_ = normals;
    has_uvs_ = uvs;
  }

  // One instance's scalar values into `row`; lists are read and dropped.
  void read_row(const Element& e, ValueReader& values, std::vector<double>& row) {
    for (std::size_t p = 0; p < e.properties.size(); ++p) {
      const Property& prop = e.properties[p];
      if (!prop.list_count) {
        row[p] = values.next(prop.type);
        continue;
      }
      const double n = values.next(*prop.list_count);
      if (!(n >= 0) || n > static_cast<double>(values.bytes_left())) fail_("a list of " + std::to_string(n) + " items");
      for (std::uint64_t k = 0; k < static_cast<std::uint64_t>(n); ++k) values.next(prop.type);
    }
  }

  void read_faces(const Element& e, ValueReader& values, MeshSource& source) {
    std::optional<std::size_t> corners_at;
    for (std::size_t p = 0; p < e.properties.size(); ++p) {
      const std::string& n = e.properties[p].name;
      if (e.properties[p].list_count && (n == "vertex_indices" || n == "vertex_index")) corners_at = p;
    }
    if (!corners_at) fail_("the face element has no vertex_indices list");
    warn_unread(e, {e.properties[*corners_at].name});
    std::vector<std::uint32_t> corners;
    for (std::uint64_t f = 0; f < e.count; ++f) {
      for (std::size_t p = 0; p < e.properties.size(); ++p) {
        const Property& prop = e.properties[p];
        if (!prop.list_count) {
          values.next(prop.type);
          continue;
        }
        const double n = values.next(*prop.list_count);
        if (!(n >= 0) || n > static_cast<double>(values.bytes_left())) {
          fail_("face " + std::to_string(f) + " has a list of " + std::to_string(n) + " items");
        }
        corners.clear();
        for (std::uint64_t k = 0; k < static_cast<std::uint64_t>(n); ++k) {
          const double index = values.next(prop.type);
          if (p != *corners_at) continue;
          if (!(index >= 0) || index >= static_cast<double>(source.positions.size()) || index != std::floor(index)) {
            fail_("face " + std::to_string(f) + " names vertex " + std::to_string(index) + ", and there are " +
                  std::to_string(source.positions.size()));
          }
          corners.push_back(static_cast<std::uint32_t>(index));
        }
        if (p == *corners_at) add_face(corners, source);
      }
      if (source.triangles.size() > limits_.max_triangles) {
        throw ImportLimitError(path_, ImportLimit::Triangles, static_cast<double>(limits_.max_triangles),
                               path_ + " has more triangles (its faces fanned) than");
      }
      if (f % 65536 == 65535) check_import_time(limits_, "reading " + path_);
    }
  }

  void add_face(const std::vector<std::uint32_t>& corners, MeshSource& source) {
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
      SourceTriangle tri;
      const std::uint32_t picks[3] = {corners[0], corners[k], corners[k + 1]};
      for (int c = 0; c < 3; ++c) {
        tri.corner[c].position = picks[c];
        if (has_normals_) tri.corner[c].normal = picks[c];
        if (has_uvs_) tri.corner[c].texcoord = picks[c];
      }
      tri.material = 0;
      source.triangles.push_back(tri);
    }
  }

  void skip(const Element& e, ValueReader& values) {
    warnings_.add(path_ + ": element \"" + e.name + "\" is not read");
    std::vector<double> row(e.properties.size());
    for (std::uint64_t i = 0; i < e.count; ++i) read_row(e, values, row);
  }

  std::string path_;
  std::string_view bytes_;
  ImportLimits limits_;
  ImportWarnings& warnings_;
  Failure fail_;
  std::vector<glm::dvec3> colours_;
  bool has_normals_ = false;
  bool has_uvs_ = false;
};

}  // namespace

Model import_ply_bundle(const Bundle& bundle, const ImportLimits& limits, const ImportChoices& choices) {
  const std::string path = find_model_file(bundle, {".ply"}, ".ply");
  ImportWarnings warnings;
  MeshSource source = PlyReader(path, *bundle.find(path), limits, warnings).read();
  apply_import_choices(source, choices);
  return build_single_material_model(source, warnings);
}

}  // namespace toond::scene
