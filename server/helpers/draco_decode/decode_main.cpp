// toond-draco-decode: decodes one Draco mesh for the daemon
// (scene/gltf/draco_decoder.h) in a process of its own, so that a decoder crash
// or runaway on a hostile file ends this process and never toond.
//   toond-draco-decode --memory-mb N --cpu-seconds S [--attribute ID]...
// Standard input: the Draco bytes. Standard output: the mesh
// (draco_decode/draco_wire.h) with the attributes asked for, in that order.
// Exit status 0 on success, 1 when the data cannot be decoded (the reason
// on standard error), 2 on a usage error.
#include <cstdio>
#include <cstring>
#include <new>
#include <optional>
#include <string>
#include <vector>

#include <draco/compression/decode.h>
#include <draco/mesh/mesh.h>

#include "helpers/draco_decode/draco_wire.h"
#include "helpers/process/resource_limits.h"
#include "helpers/process/stdio_bytes.h"

namespace {

using namespace toond;

struct Options {
  helper_process::ResourceLimits limits;
  std::vector<std::uint32_t> attributes;
};

std::optional<Options> parse_options(int argc, char** argv) {
  Options options;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    const auto value = helper_process::parse_count(argv[i + 1]);
    if (!value) return std::nullopt;
    if (flag == "--memory-mb") {
      options.limits.memory_mb = *value;
    } else if (flag == "--cpu-seconds") {
      options.limits.cpu_seconds = *value;
    } else if (flag == "--attribute" && *value <= UINT32_MAX) {
      options.attributes.push_back(static_cast<std::uint32_t>(*value));
    } else {
      return std::nullopt;
    }
  }
  if (argc % 2 != 1 || options.limits.memory_mb == 0 || options.limits.cpu_seconds == 0) return std::nullopt;
  return options;
}

int fail(const std::string& why) {
  std::fprintf(stderr, "%s\n", why.c_str());
  return 1;
}

// The glTF component type that holds `type` as it is, or 0 when the values
// must be converted to float.
int gltf_type_of(draco::DataType type) {
  switch (type) {
    case draco::DT_INT8:
      return draco_wire::kByte;
    case draco::DT_UINT8:
      return draco_wire::kUnsignedByte;
    case draco::DT_INT16:
      return draco_wire::kShort;
    case draco::DT_UINT16:
      return draco_wire::kUnsignedShort;
    case draco::DT_UINT32:
      return draco_wire::kUnsignedInt;
    case draco::DT_FLOAT32:
      return draco_wire::kFloat;
    default:
      return 0;
  }
}

// The attribute's value at every point, or an empty optional with `why`.
std::optional<draco_wire::Attribute> values_of(const draco::Mesh& mesh, const draco::PointAttribute& attribute,
                                               std::string& why) {
  const std::string name = "attribute " + std::to_string(attribute.unique_id());
  const int components = attribute.num_components();
  if (components < 1 || components > 4) {
    why = name + " has " + std::to_string(components) + " components";
    return std::nullopt;
  }
  draco_wire::Attribute out;
  out.unique_id = attribute.unique_id();
  out.components = static_cast<std::uint32_t>(components);
  const int native = gltf_type_of(attribute.data_type());
  out.component_type = native != 0 ? native : draco_wire::kFloat;
  const std::size_t element = out.components * draco_wire::component_size(out.component_type);
  out.values.resize(std::size_t{mesh.num_points()} * element);
  for (draco::PointIndex p(0); p < mesh.num_points(); ++p) {
    const draco::AttributeValueIndex value = attribute.mapped_index(p);
    if (value.value() >= attribute.size()) {
      why = name + " maps point " + std::to_string(p.value()) + " to a value it does not have";
      return std::nullopt;
    }
    std::uint8_t* target = out.values.data() + std::size_t{p.value()} * element;
    if (native != 0) {
      std::memcpy(target, attribute.GetAddress(value), element);
    } else {
      float converted[4] = {};
      if (!attribute.ConvertValue<float>(value, static_cast<int8_t>(components), converted)) {
        why = name + " has values that cannot be read as numbers";
        return std::nullopt;
      }
      std::memcpy(target, converted, element);
    }
  }
  return out;
}

int decode(const Options& options) {
  const std::string input = helper_process::read_all_stdin();
  draco::DecoderBuffer buffer;
  buffer.Init(input.data(), input.size());
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
  if (!decoded.ok()) return fail("not a Draco mesh: " + decoded.status().error_msg_string());
  const draco::Mesh& mesh = *decoded.value();

  draco_wire::Mesh out;
  out.points = mesh.num_points();
  out.indices.reserve(std::size_t{mesh.num_faces()} * 3);
  for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f) {
    for (const draco::PointIndex& corner : mesh.face(f)) out.indices.push_back(corner.value());
  }
  for (const std::uint32_t id : options.attributes) {
    const draco::PointAttribute* attribute = mesh.GetAttributeByUniqueId(id);
    if (!attribute) return fail("the Draco mesh has no attribute with id " + std::to_string(id));
    std::string why;
    auto values = values_of(mesh, *attribute, why);
    if (!values) return fail(why);
    out.attributes.push_back(std::move(*values));
  }
  if (!helper_process::write_all_stdout(draco_wire::write_mesh(out))) return fail("cannot write the answer");
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const auto options = parse_options(argc, argv);
  if (!options) {
    std::fprintf(stderr, "usage: toond-draco-decode --memory-mb N --cpu-seconds S [--attribute ID]... < data.drc\n");
    return 2;
  }
  helper_process::apply_resource_limits(options->limits);
  try {
    return decode(*options);
  } catch (const std::bad_alloc&) {
    return fail("decoding needs more than the memory limit of " + std::to_string(options->limits.memory_mb) + " MB");
  } catch (const std::exception& e) {
    return fail(std::string("the decoder failed: ") + e.what());
  }
}
