#pragma once
// STL and PLY files written here, in every form the readers take, from one
// list of triangles: the same mesh as binary and ASCII STL, and as ASCII
// and binary (both byte orders) PLY.
#include <array>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace toond::test {

struct Triangles {
  std::vector<glm::dvec3> positions;
  std::vector<std::array<unsigned, 3>> faces;
};

// A unit cube, 8 positions, 12 triangles wound counter-clockwise from
// outside.
Triangles cube_triangles();
// A grid of columns × rows quads (two triangles each) over the unit square
// in the XY plane, gently waved in z.
Triangles wavy_grid(int columns, int rows);

// `header` fills the 80 header bytes (a header starting "solid" is allowed
// in binary files, and common).
std::string binary_stl(const Triangles& mesh, const std::string& header = "toond test");
std::string ascii_stl(const Triangles& mesh);

// OBJ: v lines and triangle faces, no normals.
std::string obj(const Triangles& mesh);

enum class PlyForm { Ascii, BinaryLittle, BinaryBig };
// Vertices x y z (float), faces as a uchar-counted int list named
// vertex_indices.
std::string ply(const Triangles& mesh, PlyForm form);

}  // namespace toond::test
