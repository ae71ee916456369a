// toond-test-draco-encode: Draco's own encoder for the tests, in a program
// of its own. Debian's libdraco carries a copy of tinygltf of its own, so
// Draco cannot share a process with the importer (the same reason the
// daemon decodes in a helper).
//   toond-test-draco-encode --bits N --type position|normal|color|texcoord|generic ...
// Standard input: a mesh in the decoder helper's wire format
// (draco_decode/draco_wire.h), float attributes, one --type per attribute in
// order. Standard output: "TDE1", then as u32s the decoded mesh's points and
// faces, the attribute count and each attribute's Draco id, then the Draco
// bytes.
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <iterator>
#include <string>
#include <vector>

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>

#include "helpers/draco_decode/draco_wire.h"
#include "helpers/process/stdio_bytes.h"

namespace {

using namespace toond;

void put_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}

draco::GeometryAttribute::Type type_named(const std::string& name) {
  if (name == "position") return draco::GeometryAttribute::POSITION;
  if (name == "normal") return draco::GeometryAttribute::NORMAL;
  if (name == "color") return draco::GeometryAttribute::COLOR;
  if (name == "texcoord") return draco::GeometryAttribute::TEX_COORD;
  return draco::GeometryAttribute::GENERIC;
}

int fail(const std::string& why) {
  std::fprintf(stderr, "toond-test-draco-encode: %s\n", why.c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  int bits = 0;
  std::vector<draco::GeometryAttribute::Type> types;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--bits") bits = std::atoi(argv[i + 1]);
    if (flag == "--type") types.push_back(type_named(argv[i + 1]));
  }
  const draco_wire::Mesh input = draco_wire::read_mesh(helper_process::read_all_stdin());
  if (input.attributes.size() != types.size()) return fail("one --type per attribute, please");

  draco::Mesh mesh;
  mesh.set_num_points(input.points);
  std::vector<std::uint32_t> ids;
  for (std::size_t k = 0; k < input.attributes.size(); ++k) {
    const draco_wire::Attribute& values = input.attributes[k];
    if (values.component_type != draco_wire::kFloat) return fail("float attributes only");
    const auto components = static_cast<int8_t>(values.components);
    draco::GeometryAttribute attribute;
    attribute.Init(types[k], nullptr, components, draco::DT_FLOAT32, false, int64_t{components} * 4, 0);
    const int id = mesh.AddAttribute(attribute, true, input.points);
    for (std::uint32_t p = 0; p < input.points; ++p) {
      mesh.attribute(id)->SetAttributeValue(draco::AttributeValueIndex(p),
                                            values.values.data() + std::size_t{p} * values.components * 4);
    }
    ids.push_back(mesh.attribute(id)->unique_id());
  }
  for (std::size_t f = 0; f + 2 < input.indices.size(); f += 3) {
    mesh.AddFace({draco::PointIndex(input.indices[f]), draco::PointIndex(input.indices[f + 1]),
                  draco::PointIndex(input.indices[f + 2])});
  }

  draco::Encoder encoder;
  if (bits > 0) {
    for (const auto type :
         {draco::GeometryAttribute::POSITION, draco::GeometryAttribute::NORMAL, draco::GeometryAttribute::COLOR,
          draco::GeometryAttribute::TEX_COORD, draco::GeometryAttribute::GENERIC}) {
      encoder.SetAttributeQuantization(type, bits);
    }
  }
  draco::EncoderBuffer encoded;
  if (!encoder.EncodeMeshToBuffer(mesh, &encoded).ok()) return fail("Draco cannot encode the mesh");

  // The decoded mesh's counts are what a glTF's accessors must say.
  draco::DecoderBuffer again;
  again.Init(encoded.data(), encoded.size());
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&again);
  if (!decoded.ok()) return fail("Draco cannot decode what it encoded");

  std::string out = "TDE1";
  put_u32(out, decoded.value()->num_points());
  put_u32(out, decoded.value()->num_faces());
  put_u32(out, static_cast<std::uint32_t>(ids.size()));
  for (const std::uint32_t id : ids) put_u32(out, id);
  out.append(encoded.data(), encoded.size());
  return helper_process::write_all_stdout(out) ? 0 : 1;
}
