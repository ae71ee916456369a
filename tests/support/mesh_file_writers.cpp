#include "support/mesh_file_writers.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>

namespace toond::test {
namespace {

void put_u32_le(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xff));
}

void put_bytes(std::string& out, std::uint32_t bits, int bytes, bool little) {
  for (int i = 0; i < bytes; ++i) {
    const int shift = 8 * (little ? i : bytes - 1 - i);
    out.push_back(static_cast<char>((bits >> shift) & 0xff));
  }
}

std::uint32_t float_bits(double v) {
  const float f = static_cast<float>(v);
  std::uint32_t bits = 0;
  std::memcpy(&bits, &f, sizeof bits);
  return bits;
}

std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(static_cast<float>(v)));
  return buf;
}

}  // namespace

Triangles cube_triangles() {
  Triangles m;
  for (int i = 0; i < 8; ++i) m.positions.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  const unsigned quads[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3}, {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
  for (const auto& q : quads) {
    m.faces.push_back({q[0], q[1], q[2]});
    m.faces.push_back({q[0], q[2], q[3]});
  }
  return m;
}

Triangles wavy_grid(int columns, int rows) {
  Triangles m;
  for (int y = 0; y <= rows; ++y) {
    for (int x = 0; x <= columns; ++x) {
      const double u = double(x) / columns, v = double(y) / rows;
      m.positions.push_back({u, v, 0.05 * std::sin(6.0 * u) * std::cos(5.0 * v)});
    }
  }
  const auto at = [columns](int x, int y) { return static_cast<unsigned>(y * (columns + 1) + x); };
  for (int y = 0; y < rows; ++y) {
    for (int x = 0; x < columns; ++x) {
      m.faces.push_back({at(x, y), at(x + 1, y), at(x + 1, y + 1)});
      m.faces.push_back({at(x, y), at(x + 1, y + 1), at(x, y + 1)});
    }
  }
  return m;
}

std::string binary_stl(const Triangles& mesh, const std::string& header) {
  std::string out = header.substr(0, 80);
  out.resize(80, ' ');
  put_u32_le(out, static_cast<std::uint32_t>(mesh.faces.size()));
  for (const auto& f : mesh.faces) {
    for (int k = 0; k < 3; ++k) put_u32_le(out, 0);  // the normal, which readers ignore
    for (unsigned i : f) {
      for (int k = 0; k < 3; ++k) put_u32_le(out, float_bits(mesh.positions[i][k]));
    }
    out += std::string(2, '\0');
  }
  return out;
}

std::string ascii_stl(const Triangles& mesh) {
  std::string out = "solid test\n";
  for (const auto& f : mesh.faces) {
    out += "  facet normal 0 0 0\n    outer loop\n";
    for (unsigned i : f) {
      const glm::dvec3& p = mesh.positions[i];
      out += "      vertex " + number(p.x) + " " + number(p.y) + " " + number(p.z) + "\n";
    }
    out += "    endloop\n  endfacet\n";
  }
  return out + "endsolid test\n";
}

std::string obj(const Triangles& mesh) {
  std::string out;
  for (const glm::dvec3& p : mesh.positions) out += "v " + number(p.x) + " " + number(p.y) + " " + number(p.z) + "\n";
  for (const auto& f : mesh.faces) {
    out += "f " + std::to_string(f[0] + 1) + " " + std::to_string(f[1] + 1) + " " + std::to_string(f[2] + 1) + "\n";
  }
  return out;
}

std::string ply(const Triangles& mesh, PlyForm form) {
  const char* format = form == PlyForm::Ascii          ? "ascii"
                       : form == PlyForm::BinaryLittle ? "binary_little_endian"
                                                       : "binary_big_endian";
  std::string out = std::string("ply\nformat ") + format + " 1.0\ncomment written by toond's tests\n" +
                    "element vertex " + std::to_string(mesh.positions.size()) +
                    "\nproperty float x\nproperty float y\nproperty float z\n" + "element face " +
                    std::to_string(mesh.faces.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  const bool little = form == PlyForm::BinaryLittle;
  for (const glm::dvec3& p : mesh.positions) {
    if (form == PlyForm::Ascii) {
      out += number(p.x) + " " + number(p.y) + " " + number(p.z) + "\n";
    } else {
      for (int k = 0; k < 3; ++k) put_bytes(out, float_bits(p[k]), 4, little);
    }
  }
  for (const auto& f : mesh.faces) {
    if (form == PlyForm::Ascii) {
      out += "3 " + std::to_string(f[0]) + " " + std::to_string(f[1]) + " " + std::to_string(f[2]) + "\n";
    } else {
      out.push_back(3);
      for (unsigned i : f) put_bytes(out, i, 4, little);
    }
  }
  return out;
}

}  // namespace toond::test
