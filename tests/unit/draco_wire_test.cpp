// The Draco helper's answer is read trusting nothing: every size must add
// up and every index must name a point.
#include <gtest/gtest.h>

#include "helpers/draco_decode/draco_wire.h"

namespace toond::draco_wire {
namespace {

Mesh triangle() {
  Mesh mesh;
  mesh.points = 3;
  mesh.indices = {0, 1, 2};
  Attribute position;
  position.unique_id = 4;
  position.component_type = kFloat;
  position.components = 3;
  position.values.assign(3 * 3 * 4, 0);
  Attribute colour;
  colour.unique_id = 9;
  colour.component_type = kUnsignedByte;
  colour.components = 4;
  colour.values.assign(3 * 4, 200);
  mesh.attributes = {position, colour};
  return mesh;
}

std::string error_of(std::string_view bytes) {
  try {
    read_mesh(bytes);
  } catch (const WireError& e) {
    return e.what();
  }
  return "read";
}

TEST(DracoWire, AMeshRoundTrips) {
  const Mesh back = read_mesh(write_mesh(triangle()));
  EXPECT_EQ(back.points, 3u);
  EXPECT_EQ(back.indices, (std::vector<std::uint32_t>{0, 1, 2}));
  ASSERT_EQ(back.attributes.size(), 2u);
  EXPECT_EQ(back.attributes[1].unique_id, 9u);
  EXPECT_EQ(back.attributes[1].component_type, kUnsignedByte);
  EXPECT_EQ(back.attributes[1].values, std::vector<std::uint8_t>(12, 200));
}

TEST(DracoWire, EveryCutOfTheAnswerIsRefused) {
  const std::string bytes = write_mesh(triangle());
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    EXPECT_NE(error_of(std::string_view(bytes).substr(0, n)), "read") << n << " bytes";
  }
  EXPECT_NE(error_of(bytes + "x").find("past its end"), std::string::npos);
}

TEST(DracoWire, IndicesPastThePointsAndUnknownTypesAreRefused) {
  Mesh mesh = triangle();
  mesh.indices[2] = 3;
  EXPECT_NE(error_of(write_mesh(mesh)).find("the index 3, past its 3 points"), std::string::npos);
  mesh = triangle();
  mesh.attributes[0].component_type = 5124;  // INT, not a glTF vertex type
  EXPECT_NE(error_of(write_mesh(mesh)).find("unknown component type"), std::string::npos);
  mesh = triangle();
  mesh.indices.pop_back();
  EXPECT_NE(error_of(write_mesh(mesh)).find("not whole triangles"), std::string::npos);
  EXPECT_NE(error_of("TDM2" + write_mesh(triangle()).substr(4)).find("does not start with"), std::string::npos);
}

}  // namespace
}  // namespace toond::draco_wire
