#include "scene/gltf/gltf_meshopt.h"

#include <meshoptimizer.h>
#include <tiny_gltf.h>

#include <limits>

#include "scene/gltf/gltf_json.h"
#include "scene/reading/import_error.h"

namespace toond::scene {
namespace {

using namespace gltf_json;

// Every mode of the format spends at least two header bits on each 16
// decoded bytes (attributes; the index modes need far more), so a stream
// can never unpack to more than 64 times its own size. A count beyond that
// is refused before the output is allocated.
constexpr std::uint64_t kMaxExpansion = 64;

std::string view_name(int view) { return "buffer view " + std::to_string(view); }

[[noreturn]] void refuse(const std::string& file, int view, const std::string& why) {
  throw ImportError(file, file + ": " + view_name(view) + " (EXT_meshopt_compression) " + why);
}

std::optional<MeshoptMode> mode_named(const json& value) {
  if (!value.is_string()) return std::nullopt;
  const auto name = value.get<std::string>();
  if (name == "ATTRIBUTES") return MeshoptMode::Attributes;
  if (name == "TRIANGLES") return MeshoptMode::Triangles;
  if (name == "INDICES") return MeshoptMode::Indices;
  return std::nullopt;
}

std::optional<MeshoptFilter> filter_named(const json& value) {
  if (value.is_null()) return MeshoptFilter::None;
  if (!value.is_string()) return std::nullopt;
  const auto name = value.get<std::string>();
  if (name == "NONE") return MeshoptFilter::None;
  if (name == "OCTAHEDRAL") return MeshoptFilter::Octahedral;
  if (name == "QUATERNION") return MeshoptFilter::Quaternion;
  if (name == "EXPONENTIAL") return MeshoptFilter::Exponential;
  return std::nullopt;
}

// What the extension allows for each mode and filter; empty when allowed.
std::string stride_problem(const MeshoptStream& s) {
  const std::string stride = std::to_string(s.byte_stride);
  if (s.mode == MeshoptMode::Attributes) {
    if (s.byte_stride == 0 || s.byte_stride % 4 != 0 || s.byte_stride > 256) {
      return "has byteStride " + stride + "; attribute streams need a multiple of 4 up to 256";
    }
  } else {
    if (s.byte_stride != 2 && s.byte_stride != 4) return "has byteStride " + stride + "; index streams need 2 or 4";
    if (s.filter != MeshoptFilter::None) return "has a filter, which index streams cannot have";
    if (s.mode == MeshoptMode::Triangles && s.count % 3 != 0) {
      return "has count " + std::to_string(s.count) + ", not a whole number of triangles";
    }
  }
  if (s.filter == MeshoptFilter::Octahedral && s.byte_stride != 4 && s.byte_stride != 8) {
    return "has byteStride " + stride + "; the octahedral filter needs 4 or 8";
  }
  if (s.filter == MeshoptFilter::Quaternion && s.byte_stride != 8) {
    return "has byteStride " + stride + "; the quaternion filter needs 8";
  }
  return {};
}

void check_count_limit(const MeshoptStream& s, int view, const ImportLimits& limits, const std::string& file) {
  if (s.mode == MeshoptMode::Attributes) {
    if (s.count > limits.max_vertices) {
      throw ImportLimitError(
          file, ImportLimit::Vertices, static_cast<double>(limits.max_vertices),
          file + ": " + view_name(view) + " decompresses to " + std::to_string(s.count) + " vertices, more than");
    }
    return;
  }
  // Indices of a strip or fan make one triangle per index past the second.
  const std::uint64_t max_triangles = limits.max_triangles;
  const std::uint64_t max_corners = max_triangles > (std::numeric_limits<std::uint64_t>::max() - 2) / 3
                                        ? std::numeric_limits<std::uint64_t>::max()
                                        : max_triangles * 3 + 2;
  if (s.count > max_corners) {
    throw ImportLimitError(
        file, ImportLimit::Triangles, static_cast<double>(limits.max_triangles),
        file + ": " + view_name(view) + " decompresses to " + std::to_string(s.count) + " indices, more than",
        " allows");
  }
}

void apply_filter(MeshoptFilter filter, std::vector<std::uint8_t>& data, std::size_t count, std::size_t stride) {
  switch (filter) {
    case MeshoptFilter::None:
      return;
    case MeshoptFilter::Octahedral:
      meshopt_decodeFilterOct(data.data(), count, stride);
      return;
    case MeshoptFilter::Quaternion:
      meshopt_decodeFilterQuat(data.data(), count, stride);
      return;
    case MeshoptFilter::Exponential:
      meshopt_decodeFilterExp(data.data(), count, stride);
      return;
  }
}

}  // namespace

std::optional<MeshoptStream> parse_meshopt_stream(const json& view_json, int view, const std::string& file) {
  const json& ext = member(member(view_json, "extensions"), "EXT_meshopt_compression");
  if (ext.is_null()) return std::nullopt;
  if (!ext.is_object()) refuse(file, view, "is not a JSON object");
  const auto required = [&](const char* key) {
    const auto value = unsigned_of(member(ext, key));
    if (!value) refuse(file, view, std::string("has no valid ") + key);
    return *value;
  };
  MeshoptStream s;
  s.buffer = index_or(member(ext, "buffer"), -1);
  if (s.buffer < 0) refuse(file, view, "has no valid buffer");
  s.byte_length = required("byteLength");
  s.byte_stride = required("byteStride");
  s.count = required("count");
  if (!member(ext, "byteOffset").is_null()) s.byte_offset = required("byteOffset");
  const auto mode = mode_named(member(ext, "mode"));
  if (!mode) refuse(file, view, "has no mode ATTRIBUTES, TRIANGLES or INDICES");
  s.mode = *mode;
  const auto filter = filter_named(member(ext, "filter"));
  if (!filter) refuse(file, view, "has a filter other than NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL");
  s.filter = *filter;
  if (const std::string problem = stride_problem(s); !problem.empty()) refuse(file, view, problem);

  // The view itself describes the decompressed bytes.
  if (const auto stride = unsigned_of(member(view_json, "byteStride")); stride && *stride != s.byte_stride) {
    refuse(file, view, "has byteStride " + std::to_string(s.byte_stride) + " but its view " + std::to_string(*stride));
  }
  const auto view_length = unsigned_of(member(view_json, "byteLength"));
  const bool fits = s.count <= std::numeric_limits<std::uint64_t>::max() / s.byte_stride;
  if (!fits || !view_length || *view_length != s.count * s.byte_stride) {
    refuse(file, view,
           "has " + std::to_string(s.count) + " elements of " + std::to_string(s.byte_stride) +
               " bytes, which is not its view's byteLength " +
               (view_length ? std::to_string(*view_length) : std::string("(none)")));
  }
  return s;
}

std::vector<std::uint8_t> decode_meshopt_stream(const MeshoptStream& s, std::span<const std::uint8_t> buffer, int view,
                                                const ImportLimits& limits, const std::string& file) {
  if (s.byte_offset > buffer.size() || s.byte_length > buffer.size() - s.byte_offset) {
    refuse(file, view,
           "reads bytes " + std::to_string(s.byte_offset) + " + " + std::to_string(s.byte_length) +
               ", past the end of buffer " + std::to_string(s.buffer) + " (" + std::to_string(buffer.size()) +
               " bytes)");
  }
  if (s.byte_stride == 0 || (s.mode == MeshoptMode::Attributes && s.byte_stride > 256)) {
    refuse(file, view, "has byteStride " + std::to_string(s.byte_stride));
  }
  check_count_limit(s, view, limits, file);
  if (s.count > s.byte_length * kMaxExpansion / s.byte_stride) {
    refuse(file, view,
           "declares " + std::to_string(s.count) + " elements of " + std::to_string(s.byte_stride) +
               " bytes, more than its " + std::to_string(s.byte_length) + " compressed bytes can hold");
  }
  const auto count = static_cast<std::size_t>(s.count);
  const auto stride = static_cast<std::size_t>(s.byte_stride);
  std::vector<std::uint8_t> out(count * stride);
  if (count == 0) return out;
  const unsigned char* source = buffer.data() + s.byte_offset;
  const auto length = static_cast<std::size_t>(s.byte_length);
  int status = 0;
  switch (s.mode) {
    case MeshoptMode::Attributes:
      status = meshopt_decodeVertexBuffer(out.data(), count, stride, source, length);
      break;
    case MeshoptMode::Triangles:
      status = meshopt_decodeIndexBuffer(out.data(), count, stride, source, length);
      break;
    case MeshoptMode::Indices:
      status = meshopt_decodeIndexSequence(out.data(), count, stride, source, length);
      break;
  }
  if (status != 0) {
    refuse(file, view,
           "cannot be decoded (meshoptimizer error " + std::to_string(status) +
               "): the compressed stream is truncated or damaged");
  }
  apply_filter(s.filter, out, count, stride);
  return out;
}

bool is_meshopt_fallback(const json& buffer_json, bool has_data, bool file_uses_meshopt) {
  const json& tagged = member(member(member(buffer_json, "extensions"), "EXT_meshopt_compression"), "fallback");
  if (tagged.is_boolean() && tagged.get<bool>()) return true;
  return !has_data && file_uses_meshopt;
}

MeshoptViews::MeshoptViews(const json& doc, const tinygltf::Model& gltf, std::set<int> fallbacks, std::string file,
                           ImportLimits limits)
    : doc_(doc), gltf_(gltf), fallbacks_(std::move(fallbacks)), file_(std::move(file)), limits_(limits) {}

std::optional<std::span<const std::uint8_t>> MeshoptViews::bytes(int view) {
  if (const auto it = decoded_.find(view); it != decoded_.end()) return std::span<const std::uint8_t>(it->second);
  if (view < 0 || static_cast<std::size_t>(view) >= gltf_.bufferViews.size()) return std::nullopt;
  const auto stream =
      parse_meshopt_stream(element(member(doc_, "bufferViews"), static_cast<std::size_t>(view)), view, file_);
  if (!stream) {
    const int buffer = gltf_.bufferViews[static_cast<std::size_t>(view)].buffer;
    if (fallbacks_.contains(buffer)) {
      throw ImportError(file_, file_ + ": " + view_name(view) + " lies in buffer " + std::to_string(buffer) +
                                   ", which only stands in for views compressed with EXT_meshopt_compression and "
                                   "holds no data");
    }
    return std::nullopt;
  }
  if (static_cast<std::size_t>(stream->buffer) >= gltf_.buffers.size()) {
    refuse(file_, view, "refers to buffer " + std::to_string(stream->buffer) + ", which does not exist");
  }
  if (fallbacks_.contains(stream->buffer)) {
    refuse(file_, view,
           "takes its compressed bytes from buffer " + std::to_string(stream->buffer) +
               ", a fallback buffer that holds no data");
  }
  const auto& source = gltf_.buffers[static_cast<std::size_t>(stream->buffer)].data;
  auto decoded = decode_meshopt_stream(*stream, source, view, limits_, file_);
  return std::span<const std::uint8_t>(decoded_.emplace(view, std::move(decoded)).first->second);
}

}  // namespace toond::scene
