#include "helpers/draco_decode/draco_wire.h"

#include <cstring>

namespace toond::draco_wire {
namespace {

constexpr std::string_view kMagic = "TDM1";

void put_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}

// Reads the wire front to back, refusing to step past its end.
class Cursor {
 public:
  explicit Cursor(std::string_view bytes) : bytes_(bytes) {}

  std::uint32_t u32(const char* what) {
    const std::string_view b = take(4, what);
    std::uint32_t v = 0;
    for (int i = 0; i < 4; ++i)
      v |= static_cast<std::uint32_t>(static_cast<unsigned char>(b[static_cast<std::size_t>(i)])) << (8 * i);
    return v;
  }

  std::string_view take(std::uint64_t size, const char* what) {
    if (size > bytes_.size() - at_) throw WireError(std::string("the answer ends inside ") + what);
    const std::string_view out = bytes_.substr(at_, static_cast<std::size_t>(size));
    at_ += static_cast<std::size_t>(size);
    return out;
  }

  std::size_t left() const { return bytes_.size() - at_; }

 private:
  std::string_view bytes_;
  std::size_t at_ = 0;
};

}  // namespace

std::size_t component_size(int component_type) {
  switch (component_type) {
    case kByte:
    case kUnsignedByte:
      return 1;
    case kShort:
    case kUnsignedShort:
      return 2;
    case kUnsignedInt:
    case kFloat:
      return 4;
    default:
      return 0;
  }
}

std::string write_mesh(const Mesh& mesh) {
  std::string out(kMagic);
  put_u32(out, mesh.points);
  put_u32(out, static_cast<std::uint32_t>(mesh.indices.size()));
  put_u32(out, static_cast<std::uint32_t>(mesh.attributes.size()));
  for (const std::uint32_t i : mesh.indices) put_u32(out, i);
  for (const Attribute& a : mesh.attributes) {
    put_u32(out, a.unique_id);
    put_u32(out, static_cast<std::uint32_t>(a.component_type));
    put_u32(out, a.components);
    out.append(reinterpret_cast<const char*>(a.values.data()), a.values.size());
  }
  return out;
}

Mesh read_mesh(std::string_view bytes) {
  Cursor in(bytes);
  if (in.take(kMagic.size(), "its header") != kMagic)
    throw WireError("the answer does not start with " + std::string(kMagic));
  Mesh mesh;
  mesh.points = in.u32("its header");
  const std::uint32_t index_count = in.u32("its header");
  const std::uint32_t attribute_count = in.u32("its header");
  if (index_count % 3 != 0)
    throw WireError("the answer has " + std::to_string(index_count) + " indices, not whole triangles");
  if (index_count > in.left() / 4) throw WireError("the answer ends inside its indices");
  mesh.indices.resize(index_count);
  for (std::uint32_t& i : mesh.indices) {
    i = in.u32("its indices");
    if (i >= mesh.points) {
      throw WireError("the answer has the index " + std::to_string(i) + ", past its " + std::to_string(mesh.points) +
                      " points");
    }
  }
  for (std::uint32_t k = 0; k < attribute_count; ++k) {
    Attribute a;
    a.unique_id = in.u32("an attribute header");
    a.component_type = static_cast<int>(in.u32("an attribute header"));
    a.components = in.u32("an attribute header");
    const std::size_t size = component_size(a.component_type);
    if (size == 0) throw WireError("attribute " + std::to_string(a.unique_id) + " has an unknown component type");
    if (a.components < 1 || a.components > 4) {
      throw WireError("attribute " + std::to_string(a.unique_id) + " has " + std::to_string(a.components) +
                      " components");
    }
    const std::uint64_t length = std::uint64_t{mesh.points} * a.components * size;
    const std::string_view values = in.take(length, "its attribute values");
    a.values.assign(values.begin(), values.end());
    mesh.attributes.push_back(std::move(a));
  }
  if (in.left() != 0) throw WireError("the answer has " + std::to_string(in.left()) + " bytes past its end");
  return mesh;
}

}  // namespace toond::draco_wire
