#include "scene/import/iqm_import.h"

#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>

#include "glb/glb_container.h"
#include "scene/gltf/gltf_import.h"
#include "scene/reading/import_error.h"

namespace toond::scene {
namespace {

using nlohmann::json;

constexpr std::size_t kHeaderBytes = 124;
constexpr std::string_view kMagic{"INTERQUAKEMODEL\0", 16};

// The header's fields after the magic, in the order the format lists them.
enum Field : std::size_t {
  kVersion,
  kFileSize,
  kFlags,
  kTextCount,
  kTextOffset,
  kMeshCount,
  kMeshOffset,
  kArrayCount,
  kVertexCount,
  kArrayOffset,
  kTriangleCount,
  kTriangleOffset,
  kAdjacencyOffset,
  kJointCount,
  kJointOffset,
  kPoseCount,
  kPoseOffset,
  kClipCount,
  kClipOffset,
  kFrameCount,
  kFrameChannels,
  kFrameOffset,
  kFieldCount = 27
};

// Vertex array types and component formats.
enum ArrayType : std::uint32_t { kPosition = 0, kTexcoord = 1, kNormal = 2, kBlendIndexes = 4, kBlendWeights = 5 };
enum Format : std::uint32_t { kByte, kUbyte, kShort, kUshort, kInt, kUint, kHalf, kFloat, kDouble };

struct IqmMesh {
  std::string name;
  std::string material;
  std::uint32_t first_vertex = 0;
  std::uint32_t vertex_count = 0;
  std::uint32_t first_triangle = 0;
  std::uint32_t triangle_count = 0;
};

struct IqmJoint {
  std::string name;
  int parent = -1;
  glm::dvec3 translation{0.0};
  glm::dquat rotation{1.0, 0.0, 0.0, 0.0};
  glm::dvec3 scale{1.0};
};

struct IqmPose {
  int parent = -1;
  std::uint32_t mask = 0;
  std::array<float, 10> offset{};
  std::array<float, 10> scale{};
};

struct IqmClip {
  std::string name;
  std::uint32_t first_frame = 0;
  std::uint32_t frame_count = 0;
  double frame_rate = 0;
};

struct IqmFile {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::vec2> texcoords;
  std::vector<std::array<std::uint16_t, 4>> blend_joints;
  std::vector<glm::vec4> blend_weights;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<IqmMesh> meshes;
  std::vector<IqmJoint> joints;
  std::vector<IqmPose> poses;
  std::vector<IqmClip> clips;
  std::vector<std::uint16_t> frames;
  std::uint32_t frame_channels = 0;
};

// Reads one IQM file's bytes, every offset and count checked against them.
class IqmReader {
 public:
  IqmReader(std::string_view bytes, std::string path) : bytes_(bytes), path_(std::move(path)) {}

  IqmFile read() {
    if (bytes_.size() < kHeaderBytes || bytes_.substr(0, kMagic.size()) != kMagic) fail("not an IQM file");
    for (std::size_t i = 0; i < kFieldCount; ++i) header_[i] = u32(16 + 4 * i);
    if (header_[kVersion] != 2) fail("IQM version " + std::to_string(header_[kVersion]) + "; toond reads version 2");
    if (header_[kFileSize] > bytes_.size()) fail("the header says the file is longer than it is");
    IqmFile file;
    read_text();
    read_vertices(file);
    read_triangles(file);
    read_meshes(file);
    read_joints(file);
    read_poses(file);
    read_clips(file);
    return file;
  }

 private:
  [[noreturn]] void fail(const std::string& why) const { throw ImportError(path_, path_ + ": " + why); }

  std::uint32_t u32(std::size_t at) const {
    std::uint32_t v = 0;
    std::memcpy(&v, bytes_.data() + at, 4);
    return v;
  }
  float f32(std::size_t at) const {
    float v = 0;
    std::memcpy(&v, bytes_.data() + at, 4);
    return std::isfinite(v) ? v : 0.0f;
  }

  // `count` records of `size` bytes at `offset` lie inside the file.
  void need(std::uint64_t offset, std::uint64_t count, std::uint64_t size, const char* what) const {
    if (count == 0) return;
    if (count > bytes_.size() / size || offset > bytes_.size() || count * size > bytes_.size() - offset) {
      fail(std::string("its ") + what + " lie outside the file");
    }
  }

  std::string text_at(std::uint32_t offset) const {
    if (offset >= text_.size()) return {};
    const std::size_t end = text_.find('\0', offset);
    return std::string(text_.substr(offset, end == std::string_view::npos ? std::string_view::npos : end - offset));
  }

  void read_text() {
    need(header_[kTextOffset], header_[kTextCount], 1, "strings");
    // No strings: the offset is not checked, so it is not used either.
    if (header_[kTextCount] > 0) text_ = bytes_.substr(header_[kTextOffset], header_[kTextCount]);
  }

  // Component `i` of a vertex array of `format` at `at`, as a float; integer
  // formats normalised to 0..1 when `normalized` (blend weights).
  float component(Format format, std::size_t at, bool normalized) const {
    const auto* p = reinterpret_cast<const unsigned char*>(bytes_.data() + at);
    switch (format) {
      case kByte:
        return normalized ? static_cast<signed char>(p[0]) / 127.0f : static_cast<signed char>(p[0]);
      case kUbyte:
        return normalized ? p[0] / 255.0f : p[0];
      case kShort:
      case kUshort: {
        std::uint16_t v = 0;
        std::memcpy(&v, p, 2);
        if (format == kShort)
          return normalized ? static_cast<std::int16_t>(v) / 32767.0f : static_cast<std::int16_t>(v);
        return normalized ? v / 65535.0f : v;
      }
      case kInt:
      case kUint: {
        const std::uint32_t v = u32(at);
        if (format == kInt) return static_cast<float>(static_cast<std::int32_t>(v));
        return normalized ? static_cast<float>(v / 4294967295.0) : static_cast<float>(v);
      }
      case kHalf: {
        std::uint16_t h = 0;
        std::memcpy(&h, p, 2);
        const int exponent = (h >> 10) & 0x1f;
        const float mantissa = static_cast<float>(h & 0x3ff);
        const float magnitude = exponent == 0    ? std::ldexp(mantissa, -24)
                                : exponent == 31 ? 0.0f
                                                 : std::ldexp(mantissa + 1024.0f, exponent - 25);
        return (h & 0x8000) ? -magnitude : magnitude;
      }
      case kFloat:
        return f32(at);
      case kDouble: {
        double v = 0;
        std::memcpy(&v, p, 8);
        return std::isfinite(v) ? static_cast<float>(v) : 0.0f;
      }
    }
    return 0.0f;
  }

  static std::size_t component_bytes(Format format) {
    static constexpr std::array<std::size_t, 9> kBytes = {1, 1, 2, 2, 4, 4, 2, 4, 8};
    return kBytes[format];
  }

  void read_vertices(IqmFile& file) {
    const std::uint32_t count = header_[kVertexCount];
    need(header_[kArrayOffset], header_[kArrayCount], 20, "vertex arrays");
    for (std::uint32_t a = 0; a < header_[kArrayCount]; ++a) {
      const std::size_t at = header_[kArrayOffset] + 20u * a;
      const std::uint32_t type = u32(at);
      const std::uint32_t format_code = u32(at + 8);
      const std::uint32_t size = u32(at + 12);
      const std::uint32_t offset = u32(at + 16);
      if (format_code > kDouble) fail("a vertex array has an unknown component format " + std::to_string(format_code));
      const auto format = static_cast<Format>(format_code);
      const std::size_t wanted = type == kTexcoord ? 2 : (type == kBlendIndexes || type == kBlendWeights) ? 4 : 3;
      if (type != kPosition && type != kTexcoord && type != kNormal && type != kBlendIndexes && type != kBlendWeights)
        continue;  // tangents, colours and custom arrays are not drawn
      if (size < wanted || size > 16) fail("a vertex array has " + std::to_string(size) + " components");
      need(offset, static_cast<std::uint64_t>(count) * size, component_bytes(format), "vertex arrays");
      const auto value = [&](std::uint32_t v, std::uint32_t c) {
        return component(format, offset + (static_cast<std::size_t>(v) * size + c) * component_bytes(format),
                         type == kBlendWeights);
      };
      for (std::uint32_t v = 0; v < count; ++v) {
        if (type == kPosition) file.positions.emplace_back(value(v, 0), value(v, 1), value(v, 2));
        if (type == kNormal) file.normals.emplace_back(value(v, 0), value(v, 1), value(v, 2));
        if (type == kTexcoord) file.texcoords.emplace_back(value(v, 0), value(v, 1));
        if (type == kBlendWeights) file.blend_weights.emplace_back(value(v, 0), value(v, 1), value(v, 2), value(v, 3));
        if (type == kBlendIndexes) {
          std::array<std::uint16_t, 4> joints{};
          for (std::uint32_t c = 0; c < 4; ++c) {
            const float j = value(v, c);
            joints[c] = static_cast<std::uint16_t>(j >= 0.0f && j < 65535.0f ? j : 0.0f);
          }
          file.blend_joints.push_back(joints);
        }
      }
    }
    if (count > 0 && file.positions.empty()) fail("its vertices have no positions");
  }

  void read_triangles(IqmFile& file) {
    const std::uint32_t count = header_[kTriangleCount];
    need(header_[kTriangleOffset], count, 12, "triangles");
    file.triangles.resize(count);
    for (std::uint32_t t = 0; t < count; ++t) {
      for (std::uint32_t c = 0; c < 3; ++c) {
        const std::uint32_t v = u32(header_[kTriangleOffset] + 12u * t + 4u * c);
        if (v >= file.positions.size()) fail("triangle " + std::to_string(t) + " names a vertex that does not exist");
        file.triangles[t][c] = v;
      }
    }
  }

  void read_meshes(IqmFile& file) {
    need(header_[kMeshOffset], header_[kMeshCount], 24, "meshes");
    for (std::uint32_t m = 0; m < header_[kMeshCount]; ++m) {
      const std::size_t at = header_[kMeshOffset] + 24u * m;
      IqmMesh mesh{text_at(u32(at)), text_at(u32(at + 4)), u32(at + 8), u32(at + 12), u32(at + 16), u32(at + 20)};
      if (static_cast<std::uint64_t>(mesh.first_triangle) + mesh.triangle_count > file.triangles.size()) {
        fail("mesh " + std::to_string(m) + " names triangles that do not exist");
      }
      file.meshes.push_back(std::move(mesh));
    }
  }

  void read_joints(IqmFile& file) {
    need(header_[kJointOffset], header_[kJointCount], 48, "joints");
    for (std::uint32_t j = 0; j < header_[kJointCount]; ++j) {
      const std::size_t at = header_[kJointOffset] + 48u * j;
      IqmJoint joint;
      joint.name = text_at(u32(at));
      joint.parent = static_cast<std::int32_t>(u32(at + 4));
      if (joint.parent >= static_cast<int>(j)) fail("joint " + std::to_string(j) + " comes before its parent");
      if (joint.parent < 0) joint.parent = -1;
      joint.translation = {f32(at + 8), f32(at + 12), f32(at + 16)};
      joint.rotation = glm::dquat(f32(at + 32), f32(at + 20), f32(at + 24), f32(at + 28));
      joint.scale = {f32(at + 36), f32(at + 40), f32(at + 44)};
      file.joints.push_back(std::move(joint));
    }
  }

  void read_poses(IqmFile& file) {
    need(header_[kPoseOffset], header_[kPoseCount], 88, "poses");
    std::uint32_t channels = 0;
    for (std::uint32_t p = 0; p < header_[kPoseCount]; ++p) {
      const std::size_t at = header_[kPoseOffset] + 88u * p;
      IqmPose pose;
      pose.parent = static_cast<std::int32_t>(u32(at));
      if (pose.parent >= static_cast<int>(p)) fail("pose " + std::to_string(p) + " comes before its parent");
      if (pose.parent < 0) pose.parent = -1;
      pose.mask = u32(at + 4) & 0x3ff;
      for (std::size_t c = 0; c < 10; ++c) {
        pose.offset[c] = f32(at + 8 + 4 * c);
        pose.scale[c] = f32(at + 48 + 4 * c);
      }
      channels += static_cast<std::uint32_t>(std::popcount(pose.mask));
      file.poses.push_back(pose);
    }
    file.frame_channels = header_[kFrameChannels];
    if (header_[kFrameCount] > 0 && channels != file.frame_channels) {
      fail("its poses animate " + std::to_string(channels) + " channels but its frames hold " +
           std::to_string(file.frame_channels));
    }
    need(header_[kFrameOffset], static_cast<std::uint64_t>(header_[kFrameCount]) * file.frame_channels, 2, "frames");
    file.frames.resize(static_cast<std::size_t>(header_[kFrameCount]) * file.frame_channels);
    if (!file.frames.empty())
      std::memcpy(file.frames.data(), bytes_.data() + header_[kFrameOffset], file.frames.size() * 2);
  }

  void read_clips(IqmFile& file) {
    need(header_[kClipOffset], header_[kClipCount], 20, "animations");
    for (std::uint32_t a = 0; a < header_[kClipCount]; ++a) {
      const std::size_t at = header_[kClipOffset] + 20u * a;
      IqmClip clip{text_at(u32(at)), u32(at + 4), u32(at + 8), f32(at + 12)};
      if (clip.frame_count == 0 ||
          static_cast<std::uint64_t>(clip.first_frame) + clip.frame_count > header_[kFrameCount]) {
        fail("animation " + std::to_string(a) + " names frames that do not exist");
      }
      if (clip.name.empty()) clip.name = "animation " + std::to_string(a);
      file.clips.push_back(std::move(clip));
    }
  }

  std::string_view bytes_;
  std::string path_;
  std::array<std::uint32_t, kFieldCount> header_{};
  std::string_view text_;
};

// A pose's local transform in one frame.
struct Trs {
  glm::vec3 translation;
  glm::quat rotation;
  glm::vec3 scale;
};

std::vector<Trs> frame_poses(const IqmFile& file, std::uint32_t frame) {
  std::vector<Trs> out;
  std::size_t cursor = static_cast<std::size_t>(frame) * file.frame_channels;
  for (const IqmPose& pose : file.poses) {
    std::array<float, 10> v{};
    for (std::size_t c = 0; c < 10; ++c) {
      v[c] = pose.offset[c];
      if (pose.mask & (1u << c)) v[c] += static_cast<float>(file.frames[cursor++]) * pose.scale[c];
    }
    glm::quat rotation(v[6], v[3], v[4], v[5]);
    const float length = glm::length(rotation);
    rotation = length > 1e-12f ? rotation / length : glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
    out.push_back({{v[0], v[1], v[2]}, rotation, {v[7], v[8], v[9]}});
  }
  return out;
}

// A binary glTF being written: its JSON and its one buffer.
class GlbWriter {
 public:
  json doc = {{"asset", {{"version", "2.0"}, {"generator", "toond IQM reader"}}}};

  template <class T>
  int view(const std::vector<T>& items, std::optional<int> target = std::nullopt) {
    while (bin_.size() % 4 != 0) bin_.push_back('\0');
    json v = {{"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", items.size() * sizeof(T)}};
    if (target) v["target"] = *target;
    bin_.append(reinterpret_cast<const char*>(items.data()), items.size() * sizeof(T));
    doc["bufferViews"].push_back(std::move(v));
    return static_cast<int>(doc["bufferViews"].size()) - 1;
  }

  int accessor(int view, int component_type, std::size_t count, const char* type, json extra = json::object()) {
    json a = {{"bufferView", view}, {"componentType", component_type}, {"count", count}, {"type", type}};
    a.update(extra);
    doc["accessors"].push_back(std::move(a));
    return static_cast<int>(doc["accessors"].size()) - 1;
  }

  template <class Vec, int N>
  int floats(const std::vector<Vec>& items, const char* type, bool bounds = false) {
    std::vector<float> flat;
    flat.reserve(items.size() * N);
    for (const Vec& item : items) {
      for (int c = 0; c < N; ++c) flat.push_back(item[c]);
    }
    json extra = json::object();
    if (bounds && !items.empty()) {
      json lo = json::array();
      json hi = json::array();
      for (int c = 0; c < N; ++c) {
        float a = std::numeric_limits<float>::max();
        float b = std::numeric_limits<float>::lowest();
        for (const Vec& item : items) {
          a = std::min(a, static_cast<float>(item[c]));
          b = std::max(b, static_cast<float>(item[c]));
        }
        lo.push_back(a);
        hi.push_back(b);
      }
      extra = {{"min", lo}, {"max", hi}};
    }
    return accessor(view(flat), 5126, items.size(), type, extra);
  }

  std::string glb() {
    doc["buffers"] = json::array({{{"byteLength", bin_.size()}}});
    // Names come from the file's strings, which need not be UTF-8.
    return glb::glb_container(doc.dump(-1, ' ', false, json::error_handler_t::replace), bin_);
  }

 private:
  std::string bin_;
};

std::string mesh_name(const IqmMesh& mesh, std::size_t index) {
  return mesh.name.empty() ? "mesh " + std::to_string(index) : mesh.name;
}

// How the poses of a file holding clips alone land on the model's joints:
// joint index per pose, or the reason they do not.
struct PoseMap {
  std::vector<int> joint_of_pose;
  std::string refusal;
};

PoseMap map_poses(const IqmFile& model, const IqmFile& clips) {
  PoseMap map;
  if (!clips.joints.empty() && clips.joints.size() == clips.poses.size()) {
    std::map<std::string, int> by_name;
    for (std::size_t j = 0; j < model.joints.size(); ++j) by_name.emplace(model.joints[j].name, static_cast<int>(j));
    std::string missing;
    for (const IqmJoint& joint : clips.joints) {
      const auto it = by_name.find(joint.name);
      map.joint_of_pose.push_back(it == by_name.end() ? -1 : it->second);
      if (it == by_name.end() && missing.size() < 200) missing += (missing.empty() ? "'" : ", '") + joint.name + "'";
    }
    if (!missing.empty()) map.refusal = "the model has no joints named " + missing;
    return map;
  }
  if (clips.poses.size() != model.joints.size()) {
    map.refusal = "its clips move " + std::to_string(clips.poses.size()) + " joints and the model has " +
                  std::to_string(model.joints.size());
    return map;
  }
  for (std::size_t p = 0; p < clips.poses.size(); ++p) {
    if (clips.poses[p].parent != model.joints[p].parent) {
      map.refusal = "joint " + std::to_string(p) + " ('" + model.joints[p].name + "') has another parent there";
      return map;
    }
    map.joint_of_pose.push_back(static_cast<int>(p));
  }
  return map;
}

class IqmGltf {
 public:
  IqmGltf(const IqmFile& model, std::string path) : model_(model), path_(std::move(path)) {}

  void write_model() {
    write_materials();
    write_mesh();
    write_skeleton();
  }

  // The clips of `file` (this model's own, or another file's holding clips
  // alone), or a warning why they are left out.
  void write_clips(const IqmFile& file, const std::string& name, std::vector<std::string>& warnings,
                   std::vector<double>& rates) {
    if (file.clips.empty()) return;
    const PoseMap map = &file == &model_ ? identity_map() : map_poses(model_, file);
    if (!map.refusal.empty()) {
      warnings.push_back(name + ": its clips are left out: " + map.refusal);
      return;
    }
    for (const IqmClip& clip : file.clips) {
      write_clip(file, clip, map);
      rates.push_back(clip.frame_rate > 0.0 ? clip.frame_rate : kDefaultFrameRate);
    }
  }

  std::string glb() { return writer_.glb(); }

 private:
  // A clip that states no rate is keyed at Blender's default rate, the
  // rate its exporters write.
  static constexpr double kDefaultFrameRate = 24.0;

  PoseMap identity_map() const {
    PoseMap map;
    if (model_.poses.size() != model_.joints.size()) {
      map.refusal = "its poses (" + std::to_string(model_.poses.size()) + ") are not its joints (" +
                    std::to_string(model_.joints.size()) + ")";
    }
    for (std::size_t p = 0; p < model_.poses.size(); ++p) map.joint_of_pose.push_back(static_cast<int>(p));
    return map;
  }

  void write_materials() {
    for (std::size_t m = 0; m < model_.meshes.size(); ++m) {
      const IqmMesh& mesh = model_.meshes[m];
      json material = {{"name", mesh_name(mesh, m)}, {"pbrMetallicRoughness", {{"metallicFactor", 0.0}}}};
      if (!mesh.material.empty()) {
        writer_.doc["images"].push_back({{"uri", mesh.material}});
        const int image = static_cast<int>(writer_.doc["images"].size()) - 1;
        writer_.doc["textures"].push_back({{"source", image}});
        material["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", image}};
      }
      writer_.doc["materials"].push_back(std::move(material));
    }
  }

  void write_mesh() {
    json attributes = {{"POSITION", writer_.floats<glm::vec3, 3>(model_.positions, "VEC3", true)}};
    if (model_.normals.size() == model_.positions.size()) {
      std::vector<glm::vec3> normals;
      for (const glm::vec3& n : model_.normals) {
        const float length = glm::length(n);
        normals.push_back(length > 1e-12f ? n / length : glm::vec3(0.0f, 0.0f, 1.0f));
      }
      attributes["NORMAL"] = writer_.floats<glm::vec3, 3>(normals, "VEC3");
    }
    if (model_.texcoords.size() == model_.positions.size()) {
      attributes["TEXCOORD_0"] = writer_.floats<glm::vec2, 2>(model_.texcoords, "VEC2");
    }
    if (skinned()) write_influences(attributes);
    json primitives = json::array();
    for (std::size_t m = 0; m < model_.meshes.size(); ++m) {
      const IqmMesh& mesh = model_.meshes[m];
      std::vector<std::uint32_t> indices;
      for (std::uint32_t t = mesh.first_triangle; t < mesh.first_triangle + mesh.triangle_count; ++t) {
        // The format's triangles are wound clockwise; glTF's front faces
        // are counter-clockwise.
        const auto& tri = model_.triangles[t];
        indices.insert(indices.end(), {tri[0], tri[2], tri[1]});
      }
      if (indices.empty()) continue;
      const int index_view = writer_.view(indices, 34963);
      primitives.push_back({{"attributes", attributes},
                            {"indices", writer_.accessor(index_view, 5125, indices.size(), "SCALAR")},
                            {"material", m}});
    }
    if (primitives.empty()) throw ImportError(path_, path_ + ": its meshes hold no triangles");
    writer_.doc["meshes"] = json::array({{{"name", "IQM"}, {"primitives", primitives}}});
  }

  bool skinned() const {
    return !model_.joints.empty() && model_.blend_joints.size() == model_.positions.size() &&
           model_.blend_weights.size() == model_.positions.size();
  }

  void write_influences(json& attributes) {
    std::vector<std::uint16_t> joints;
    std::vector<glm::vec4> weights;
    for (std::size_t v = 0; v < model_.positions.size(); ++v) {
      glm::vec4 w = model_.blend_weights[v];
      for (int c = 0; c < 4; ++c) {
        const bool valid = model_.blend_joints[v][c] < model_.joints.size() && w[c] > 0.0f;
        joints.push_back(valid ? model_.blend_joints[v][c] : 0);
        if (!valid) w[c] = 0.0f;
      }
      const float sum = w.x + w.y + w.z + w.w;
      weights.push_back(sum > 0.0f ? w / sum : glm::vec4(1.0f, 0.0f, 0.0f, 0.0f));
    }
    attributes["JOINTS_0"] = writer_.accessor(writer_.view(joints), 5123, model_.positions.size(), "VEC4");
    attributes["WEIGHTS_0"] = writer_.floats<glm::vec4, 4>(weights, "VEC4");
  }

  void write_skeleton() {
    const std::size_t count = model_.joints.size();
    json nodes = json::array();
    std::vector<glm::dmat4> world(count);
    json roots = json::array();
    for (std::size_t j = 0; j < count; ++j) {
      const IqmJoint& joint = model_.joints[j];
      const glm::dquat rotation = glm::length(joint.rotation) > 1e-12 ? glm::normalize(joint.rotation) : glm::dquat();
      nodes.push_back({{"name", joint.name.empty() ? "joint " + std::to_string(j) : joint.name},
                       {"translation", {joint.translation.x, joint.translation.y, joint.translation.z}},
                       {"rotation", {rotation.x, rotation.y, rotation.z, rotation.w}},
                       {"scale", {joint.scale.x, joint.scale.y, joint.scale.z}}});
      const glm::dmat4 local = glm::translate(glm::dmat4(1.0), joint.translation) * glm::mat4_cast(rotation) *
                               glm::scale(glm::dmat4(1.0), joint.scale);
      world[j] = joint.parent >= 0 ? world[static_cast<std::size_t>(joint.parent)] * local : local;
      if (joint.parent < 0) roots.push_back(j);
    }
    for (std::size_t j = 0; j < count; ++j) {
      const int parent = model_.joints[j].parent;
      if (parent >= 0) nodes[static_cast<std::size_t>(parent)]["children"].push_back(j);
    }
    json mesh_node = {{"name", "IQM"}, {"mesh", 0}};
    if (skinned()) {
      std::vector<glm::mat4> inverse_binds;
      for (const glm::dmat4& m : world) inverse_binds.emplace_back(glm::inverse(m));
      std::vector<float> flat;
      for (const glm::mat4& m : inverse_binds) flat.insert(flat.end(), glm::value_ptr(m), glm::value_ptr(m) + 16);
      json joints = json::array();
      for (std::size_t j = 0; j < count; ++j) joints.push_back(j);
      writer_.doc["skins"] = json::array(
          {{{"joints", joints}, {"inverseBindMatrices", writer_.accessor(writer_.view(flat), 5126, count, "MAT4")}}});
      mesh_node["skin"] = 0;
    }
    nodes.push_back(std::move(mesh_node));
    roots.push_back(count);
    writer_.doc["nodes"] = std::move(nodes);
    writer_.doc["scenes"] = json::array({{{"nodes", roots}}});
    writer_.doc["scene"] = 0;
  }

  void write_clip(const IqmFile& file, const IqmClip& clip, const PoseMap& map) {
    const double rate = clip.frame_rate > 0.0 ? clip.frame_rate : kDefaultFrameRate;
    std::vector<float> times;
    std::vector<std::vector<Trs>> frames;
    for (std::uint32_t f = 0; f < clip.frame_count; ++f) {
      times.push_back(static_cast<float>(f / rate));
      frames.push_back(frame_poses(file, clip.first_frame + f));
    }
    const int input = writer_.accessor(writer_.view(times), 5126, times.size(), "SCALAR",
                                       {{"min", json::array({times.front()})}, {"max", json::array({times.back()})}});
    json samplers = json::array();
    json channels = json::array();
    const auto add = [&](int node, const char* path, int output) {
      samplers.push_back({{"input", input}, {"output", output}, {"interpolation", "LINEAR"}});
      channels.push_back({{"sampler", samplers.size() - 1}, {"target", {{"node", node}, {"path", path}}}});
    };
    for (std::size_t p = 0; p < map.joint_of_pose.size(); ++p) {
      const int node = map.joint_of_pose[p];
      if (node < 0) continue;
      std::vector<glm::vec3> translations;
      std::vector<glm::vec4> rotations;
      std::vector<glm::vec3> scales;
      for (const auto& frame : frames) {
        glm::quat r = frame[p].rotation;
        // Neighbouring keys on the same side of the sphere: the shorter way.
        if (!rotations.empty() && glm::dot(glm::vec4(r.x, r.y, r.z, r.w), rotations.back()) < 0.0f) r = -r;
        translations.push_back(frame[p].translation);
        rotations.emplace_back(r.x, r.y, r.z, r.w);
        scales.push_back(frame[p].scale);
      }
      add(node, "translation", writer_.floats<glm::vec3, 3>(translations, "VEC3"));
      add(node, "rotation", writer_.floats<glm::vec4, 4>(rotations, "VEC4"));
      add(node, "scale", writer_.floats<glm::vec3, 3>(scales, "VEC3"));
    }
    writer_.doc["animations"].push_back({{"name", clip.name}, {"samplers", samplers}, {"channels", channels}});
  }

  const IqmFile& model_;
  std::string path_;
  GlbWriter writer_;
};

}  // namespace

std::optional<IqmContents> iqm_contents(std::string_view bytes) {
  if (bytes.size() < kHeaderBytes || bytes.substr(0, kMagic.size()) != kMagic) return std::nullopt;
  try {
    const IqmFile file = IqmReader(bytes, "").read();
    IqmContents contents{file.meshes.size(), file.joints.size(), file.poses.size(), file.clips.size(), {}};
    for (const IqmClip& clip : file.clips) contents.clip_names.push_back(clip.name);
    return contents;
  } catch (const ImportError&) {
    return std::nullopt;
  }
}

std::string iqm_glb(const Bundle& bundle, const std::string& path, const std::vector<std::string>& clip_files,
                    std::vector<std::string>& warnings, std::vector<double>& rates, const ImportLimits& limits) {
  const std::string* content = bundle.find(path);
  if (!content) throw ImportError(path, path + ": not in the bundle");
  const IqmFile model = IqmReader(*content, path).read();
  if (model.positions.size() > limits.max_vertices) {
    throw ImportLimitError(path, ImportLimit::Vertices, static_cast<double>(limits.max_vertices),
                           path + " has " + std::to_string(model.positions.size()) + " vertices, more than");
  }
  if (model.triangles.size() > limits.max_triangles) {
    throw ImportLimitError(path, ImportLimit::Triangles, static_cast<double>(limits.max_triangles),
                           path + " has " + std::to_string(model.triangles.size()) + " triangles, more than");
  }
  if (model.meshes.empty()) throw ImportError(path, path + ": holds no mesh");
  IqmGltf gltf(model, path);
  gltf.write_model();
  gltf.write_clips(model, path, warnings, rates);
  for (const std::string& file : clip_files) {
    const IqmFile clips = IqmReader(*bundle.find(file), file).read();
    gltf.write_clips(clips, file, warnings, rates);
  }
  return gltf.glb();
}

Model import_iqm_bundle(const Bundle& bundle, const std::string& path, const std::vector<std::string>& clip_files,
                        const ImportLimits& limits, const ImportChoices& choices) {
  std::vector<std::string> warnings;
  std::vector<double> rates;
  std::string glb = iqm_glb(bundle, path, clip_files, warnings, rates, limits);
  Model imported =
      import_gltf_bundle(with_file(bundle, path, std::move(glb)), path, limits, choices, GltfOrigin::Converted);
  if (imported.rig && imported.rig->clips.size() == rates.size()) {
    auto rig = std::make_shared<Rig>(*imported.rig);
    for (std::size_t c = 0; c < rates.size(); ++c) rig->clips[c].frame_rate = rates[c];
    imported.rig = std::move(rig);
  }
  imported.warnings.insert(imported.warnings.begin(), warnings.begin(), warnings.end());
  return imported;
}

}  // namespace toond::scene
