#include "scene/gltf/gltf_accessor.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstring>

#include "scene/reading/import_error.h"

namespace toond::scene {

int gltf_component_count(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
      return 4;
    case TINYGLTF_TYPE_MAT2:
      return 4;
    case TINYGLTF_TYPE_MAT3:
      return 9;
    case TINYGLTF_TYPE_MAT4:
      return 16;
    default:
      return 0;
  }
}

std::size_t gltf_component_size(int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;  // INT and DOUBLE are not glTF 2.0 accessor types
  }
}

namespace {

double component_at(const std::uint8_t* p, int component_type, bool normalized) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const auto v = static_cast<std::int8_t>(*p);
      return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return normalized ? *p / 255.0 : *p;
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      std::int16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      std::uint16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? v / 65535.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      std::uint32_t v;
      std::memcpy(&v, p, 4);
      return normalized ? v / 4294967295.0 : v;
    }
    default: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
  }
}

std::uint32_t index_at(const std::uint8_t* p, int component_type) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return *p;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      std::uint16_t v;
      std::memcpy(&v, p, 2);
      return v;
    }
    default: {
      std::uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
  }
}

}  // namespace

// Where `count` elements of `element_size` bytes, `stride` apart, lie.
struct GltfAccessorReader::Layout {
  const std::uint8_t* first = nullptr;  // null: no buffer view, all zero
  std::size_t stride = 0;
};

GltfAccessorReader::GltfAccessorReader(const tinygltf::Model& model, std::string file, ViewOverride view_override)
    : model_(model), file_(std::move(file)), view_override_(std::move(view_override)) {}

const tinygltf::Accessor& GltfAccessorReader::accessor(int index, const std::string& role) const {
  if (index < 0 || static_cast<std::size_t>(index) >= model_.accessors.size()) {
    throw ImportError(file_, file_ + ": " + role + " refers to accessor " + std::to_string(index) +
                                 ", which does not exist (the file has " + std::to_string(model_.accessors.size()) +
                                 ")");
  }
  return model_.accessors[static_cast<std::size_t>(index)];
}

std::span<const std::uint8_t> GltfAccessorReader::view(int view, const std::string& role) const {
  if (view < 0 || static_cast<std::size_t>(view) >= model_.bufferViews.size()) {
    throw ImportError(
        file_, file_ + ": " + role + " refers to buffer view " + std::to_string(view) + ", which does not exist");
  }
  if (view_override_) {
    if (const auto bytes = view_override_(view)) return *bytes;
  }
  const tinygltf::BufferView& v = model_.bufferViews[static_cast<std::size_t>(view)];
  if (v.buffer < 0 || static_cast<std::size_t>(v.buffer) >= model_.buffers.size()) {
    throw ImportError(file_, file_ + ": buffer view " + std::to_string(view) + " refers to buffer " +
                                 std::to_string(v.buffer) + ", which does not exist");
  }
  const auto& data = model_.buffers[static_cast<std::size_t>(v.buffer)].data;
  if (v.byteOffset > data.size() || v.byteLength > data.size() - v.byteOffset) {
    throw ImportError(file_, file_ + ": buffer view " + std::to_string(view) + " (bytes " +
                                 std::to_string(v.byteOffset) + " + " + std::to_string(v.byteLength) +
                                 ") reaches past the end of buffer " + std::to_string(v.buffer) + " (" +
                                 std::to_string(data.size()) + " bytes)");
  }
  return {data.data() + v.byteOffset, v.byteLength};
}

GltfAccessorReader::Layout GltfAccessorReader::layout_of(int index, const std::string& role, int view,
                                                         std::size_t offset, std::size_t count,
                                                         std::size_t element_size, std::size_t stride) const {
  if (view < 0) return {};
  const auto bytes = this->view(view, role);
  const bool fits = count == 0 || (offset <= bytes.size() && element_size <= bytes.size() - offset &&
                                   (count - 1) <= (bytes.size() - offset - element_size) / stride);
  if (!fits) {
    throw ImportError(file_, file_ + ": accessor " + std::to_string(index) + " (" + role + ", " +
                                 std::to_string(count) + " elements of " + std::to_string(element_size) +
                                 " bytes from byte " + std::to_string(offset) +
                                 ") reaches past the end of buffer view " + std::to_string(view) + " (" +
                                 std::to_string(bytes.size()) + " bytes)");
  }
  return {bytes.data() + offset, stride};
}

std::vector<double> GltfAccessorReader::read(int index, const std::string& role, int components,
                                             std::vector<int> also_allowed, double fill) const {
  const tinygltf::Accessor& a = accessor(index, role);
  const int have = gltf_component_count(a.type);
  const std::size_t size = gltf_component_size(a.componentType);
  also_allowed.push_back(components);
  if (have == 0 || size == 0 || std::find(also_allowed.begin(), also_allowed.end(), have) == also_allowed.end()) {
    throw ImportError(file_, file_ + ": accessor " + std::to_string(index) + " (" + role +
                                 ") has a type or component type that " + role + " cannot have");
  }
  const std::size_t element = size * static_cast<std::size_t>(have);
  std::size_t stride = element;
  if (a.bufferView >= 0 && static_cast<std::size_t>(a.bufferView) < model_.bufferViews.size()) {
    const std::size_t given = model_.bufferViews[static_cast<std::size_t>(a.bufferView)].byteStride;
    if (given != 0) {
      if (given < element) {
        throw ImportError(file_, file_ + ": accessor " + std::to_string(index) + " (" + role +
                                     ") has elements larger than its buffer view's byte stride");
      }
      stride = given;
    }
  }
  const Layout layout = layout_of(index, role, a.bufferView, a.byteOffset, a.count, element, stride);
  const auto width = static_cast<std::size_t>(components);
  std::vector<double> out(a.count * width, 0.0);
  const auto take = static_cast<std::size_t>(std::min(have, components));
  const auto decode_into = [&](std::size_t i, const std::uint8_t* p) {
    for (std::size_t c = 0; c < take; ++c)
      out[i * width + c] = component_at(p + c * size, a.componentType, a.normalized);
  };
  for (std::size_t i = 0; i < a.count; ++i) {
    if (layout.first) decode_into(i, layout.first + i * layout.stride);
    for (std::size_t c = take; c < width; ++c) out[i * width + c] = fill;
  }
  if (a.sparse.isSparse) {
    const auto& s = a.sparse;
    if (s.count < 0 || static_cast<std::size_t>(s.count) > a.count || s.indices.byteOffset < 0 ||
        s.values.byteOffset < 0) {
      throw ImportError(file_, file_ + ": accessor " + std::to_string(index) + " (" + role +
                                   ") has a sparse part that does not fit it");
    }
    const auto n = static_cast<std::size_t>(s.count);
    const std::size_t index_size = gltf_component_size(s.indices.componentType);
    if (index_size == 0 || s.indices.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
        s.indices.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
        s.indices.componentType == TINYGLTF_COMPONENT_TYPE_SHORT) {
      throw ImportError(file_, file_ + ": accessor " + std::to_string(index) + " (" + role +
                                   ") has sparse indices of a type indices cannot have");
    }
    const std::string sparse_role = role + ", sparse";
    const Layout indices = layout_of(index, sparse_role + " indices", s.indices.bufferView,
                                     static_cast<std::size_t>(s.indices.byteOffset), n, index_size, index_size);
    const Layout values = layout_of(index, sparse_role + " values", s.values.bufferView,
                                    static_cast<std::size_t>(s.values.byteOffset), n, element, element);
    if (!indices.first || !values.first) {
      throw ImportError(file_, file_ + ": accessor " + std::to_string(index) + " (" + role +
                                   ") has a sparse part without its buffer views");
    }
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t target = index_at(indices.first + k * index_size, s.indices.componentType);
      if (target >= a.count) {
        throw ImportError(file_, file_ + ": accessor " + std::to_string(index) + " (" + role + ") has a sparse index " +
                                     std::to_string(target) + " past its " + std::to_string(a.count) + " elements");
      }
      decode_into(target, values.first + k * element);
    }
  }
  return out;
}

std::vector<std::uint32_t> GltfAccessorReader::read_indices(int index, const std::string& role) const {
  const tinygltf::Accessor& a = accessor(index, role);
  const int type = a.componentType;
  if (a.type != TINYGLTF_TYPE_SCALAR ||
      (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
       type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)) {
    throw ImportError(file_, file_ + ": accessor " + std::to_string(index) + " (" + role +
                                 ") is not a list of unsigned integer indices");
  }
  if (a.sparse.isSparse) {
    // Rare for indices; the general path applies the substitutions.
    const auto values = read(index, role, 1);
    std::vector<std::uint32_t> out(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) out[i] = static_cast<std::uint32_t>(values[i]);
    return out;
  }
  const std::size_t size = gltf_component_size(type);
  const Layout layout = layout_of(index, role, a.bufferView, a.byteOffset, a.count, size, size);
  std::vector<std::uint32_t> out(a.count, 0);
  if (layout.first) {
    for (std::size_t i = 0; i < a.count; ++i) out[i] = index_at(layout.first + i * size, type);
  }
  return out;
}

}  // namespace toond::scene
