#pragma once
// What moves in a glTF test model, added to the parts build_gltf made:
// accessors appended to its one buffer, then skins, morph targets and
// animations written into its JSON by the test (so each test can also
// write them wrong on purpose).
#include <cstdint>
#include <string>
#include <vector>

#include "support/gltf_writer.h"

namespace toond::test {

// Float components, `type` "SCALAR", "VEC3", "VEC4" or "MAT4"; returns the
// new accessor's index.
int append_float_accessor(GltfParts& parts, const std::vector<float>& values, const std::string& type);
// Unsigned 16-bit joint indices, four per vertex (VEC4).
int append_joints_accessor(GltfParts& parts, const std::vector<std::uint16_t>& joints);

// A bar of `rings` square rings of four vertices, one unit apart up +Y
// from the origin, side 0.4, closed with caps: what the rigged tests bend.
GltfPrimitive bar_primitive(int rings);

}  // namespace toond::test
