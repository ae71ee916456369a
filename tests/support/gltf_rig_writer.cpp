#include "support/gltf_rig_writer.h"

#include <cstring>

namespace toond::test {
namespace {

int append_accessor(GltfParts& parts, const void* bytes, std::size_t size, std::size_t count, int component_type,
                    const std::string& type) {
  while (parts.bin.size() % 4 != 0) parts.bin.push_back('\0');
  nlohmann::json& doc = parts.json;
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", parts.bin.size()}, {"byteLength", size}});
  parts.bin.append(static_cast<const char*>(bytes), size);
  doc["buffers"][0]["byteLength"] = parts.bin.size();
  doc["accessors"].push_back({{"bufferView", doc["bufferViews"].size() - 1},
                              {"componentType", component_type},
                              {"count", count},
                              {"type", type}});
  return static_cast<int>(doc["accessors"].size()) - 1;
}

}  // namespace

int append_float_accessor(GltfParts& parts, const std::vector<float>& values, const std::string& type) {
  constexpr int kFloat = 5126;
  return append_accessor(parts, values.data(), values.size() * sizeof(float), values.size() / components_of(type),
                         kFloat, type);
}

int append_joints_accessor(GltfParts& parts, const std::vector<std::uint16_t>& joints) {
  constexpr int kUnsignedShort = 5123;
  return append_accessor(parts, joints.data(), joints.size() * sizeof(std::uint16_t), joints.size() / 4, kUnsignedShort,
                         "VEC4");
}

GltfPrimitive bar_primitive(int rings) {
  GltfPrimitive bar;
  const float h = 0.2f;
  for (int r = 0; r < rings; ++r) {
    const float y = static_cast<float>(r);
    for (const auto& [x, z] : {std::pair{-h, -h}, {h, -h}, {h, h}, {-h, h}}) bar.positions.emplace_back(x, y, z);
  }
  for (int r = 0; r + 1 < rings; ++r) {
    for (std::uint32_t s = 0; s < 4; ++s) {
      const std::uint32_t a = static_cast<std::uint32_t>(r) * 4 + s,
                          b = static_cast<std::uint32_t>(r) * 4 + (s + 1) % 4;
      const std::uint32_t c = b + 4, d = a + 4;
      bar.indices.insert(bar.indices.end(), {a, c, b, a, d, c});
    }
  }
  const std::uint32_t top = static_cast<std::uint32_t>(rings - 1) * 4;
  bar.indices.insert(bar.indices.end(), {0, 1, 2, 0, 2, 3, top, top + 2, top + 1, top, top + 3, top + 2});
  return bar;
}

}  // namespace toond::test
