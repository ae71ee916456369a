#include "scene/import/demo_model.h"

#include <array>
#include <charconv>
#include <cmath>
#include <numbers>
#include <string>

#include <glm/glm.hpp>

#include "image/png_codec.h"

namespace toond::scene {
namespace {

constexpr int kSegments = 48;  // around the sphere
constexpr int kRings = 24;     // pole to pole
constexpr double kSphereRadius = 0.6;
// Sunk slightly into the box so the two parts intersect: that gives the
// screen-space edge pass a crease to find.
constexpr glm::dvec3 kSphereCentre{0.0, 0.95, 0.0};
constexpr double kBoxHalfWidth = 0.8;
constexpr double kBoxHeight = 0.4;

constexpr int kTextureWidth = 256;
constexpr int kTextureHeight = 128;

// std::to_chars ignores the C locale, so the text is the same byte for byte
// wherever the daemon runs.
std::string number(double value) {
  if (std::abs(value) < 5e-7) value = 0.0;  // no "-0.000000"
  std::array<char, 64> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value, std::chars_format::fixed, 6);
  return std::string(buffer.data(), result.ptr);
}

void append_vec(std::string& out, const char* keyword, std::initializer_list<double> values) {
  out += keyword;
  for (const double v : values) {
    out += ' ';
    out += number(v);
  }
  out += '\n';
}

std::string corner(int v, int vt, int vn) {
  std::string s = std::to_string(v) + '/';
  if (vt > 0) s += std::to_string(vt);
  return s + '/' + std::to_string(vn);
}

// Two warm tones in squares of equal size on the sphere: 8 across the full
// turn of u, 4 across the half turn of v.
std::string make_texture_png() {
  image::Image img;
  img.width = kTextureWidth;
  img.height = kTextureHeight;
  img.rgba.resize(static_cast<std::size_t>(img.width) * img.height * 4);
  constexpr std::array<std::uint8_t, 3> coral{236, 112, 86};
  constexpr std::array<std::uint8_t, 3> cream{250, 232, 196};
  constexpr std::array<std::uint8_t, 3> seam{196, 84, 70};
  const int cell = kTextureWidth / 8;
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      const bool odd = ((x / cell) + (y / cell)) % 2 == 1;
      // A thin darker line round the equator band gives the texture a
      // feature that cel banding does not erase.
      const bool line = std::abs(y - img.height / 2) < 2;
      const auto& colour = line ? seam : (odd ? coral : cream);
      std::uint8_t* p = img.pixel(x, y);
      p[0] = colour[0];
      p[1] = colour[1];
      p[2] = colour[2];
      p[3] = 255;
    }
  }
  return image::encode_png(img);
}

// An opaque grey PNG whose level at (x, y) is `level(x, y)`.
template <class Level>
std::string grey_png(int width, int height, Level level) {
  image::Image img;
  img.width = width;
  img.height = height;
  img.rgba.resize(static_cast<std::size_t>(width) * height * 4);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = img.pixel(x, y);
      p[0] = p[1] = p[2] = level(x, y);
      p[3] = 255;
    }
  }
  return image::encode_png(img);
}

// A "sharp lighting map": 16 texels, 3 shades (the
// shadow band over the first 6, a mid tone, the lit tone over the last 4),
// for `shading.ramp_image`.
std::string make_ramp_png() {
  return grey_png(16, 1, [](int x, int) -> std::uint8_t { return x < 6 ? 110 : x < 12 ? 190 : 255; });
}

// Grey tiles for `floor.texture`: 2×2 squares per repeat.
std::string make_floor_png() {
  return grey_png(64, 64, [](int x, int y) -> std::uint8_t { return ((x / 32) + (y / 32)) % 2 == 1 ? 150 : 235; });
}

void append_sphere(std::string& obj) {
  obj += "o sphere\ng sphere\nusemtl body\n";
  // Positions (and their normals, same order): top pole, rings 1..kRings-1,
  // bottom pole.
  const auto unit = [](int ring, int segment) {
    const double theta = std::numbers::pi * ring / kRings;
    const double phi = 2.0 * std::numbers::pi * segment / kSegments;
    return glm::dvec3(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi));
  };
  std::vector<glm::dvec3> directions;
  directions.push_back({0.0, 1.0, 0.0});
  for (int ring = 1; ring < kRings; ++ring) {
    for (int segment = 0; segment < kSegments; ++segment) directions.push_back(unit(ring, segment));
  }
  directions.push_back({0.0, -1.0, 0.0});
  for (const auto& d : directions) {
    const glm::dvec3 p = kSphereCentre + d * kSphereRadius;
    append_vec(obj, "v", {p.x, p.y, p.z});
  }
  for (const auto& d : directions) append_vec(obj, "vn", {d.x, d.y, d.z});
  // Texture coordinates: a (kSegments+1) x (kRings+1) grid, the seam column
  // duplicated, then one per pole triangle at the middle of its segment.
  for (int ring = 0; ring <= kRings; ++ring) {
    for (int segment = 0; segment <= kSegments; ++segment) {
      append_vec(obj, "vt", {static_cast<double>(segment) / kSegments, 1.0 - static_cast<double>(ring) / kRings});
    }
  }
  const int grid_texcoords = (kSegments + 1) * (kRings + 1);
  for (const double v : {1.0, 0.0}) {
    for (int segment = 0; segment < kSegments; ++segment) {
      append_vec(obj, "vt", {(segment + 0.5) / kSegments, v});
    }
  }

  // 1-based OBJ indices.
  const int top = 1;
  const int bottom = static_cast<int>(directions.size());
  const auto pos = [&](int ring, int segment) {
    if (ring == 0) return top;
    if (ring == kRings) return bottom;
    return 2 + (ring - 1) * kSegments + segment % kSegments;
  };
  const auto tex = [](int ring, int segment) { return 1 + ring * (kSegments + 1) + segment; };
  const auto face = [&](std::initializer_list<std::array<int, 2>> corners) {
    obj += 'f';
    for (const auto& [ring, segment] : corners) {
      obj += ' ';
      const int p = pos(ring, segment);
      int t = tex(ring, segment);
      if (ring == 0) t = grid_texcoords + 1 + segment;
      if (ring == kRings) t = grid_texcoords + kSegments + 1 + segment;
      obj += corner(p, t, p);
    }
    obj += '\n';
  };
  // Counter-clockwise seen from outside: down the ring, then along the turn.
  for (int segment = 0; segment < kSegments; ++segment) face({{0, segment}, {1, segment}, {1, segment + 1}});
  for (int ring = 1; ring + 1 < kRings; ++ring) {
    for (int segment = 0; segment < kSegments; ++segment) {
      face({{ring, segment}, {ring + 1, segment}, {ring + 1, segment + 1}, {ring, segment + 1}});
    }
  }
  for (int segment = 0; segment < kSegments; ++segment) {
    face({{kRings - 1, segment}, {kRings, segment}, {kRings - 1, segment + 1}});
  }
}

void append_box(std::string& obj, int first_position, int first_normal) {
  obj += "o base\ng base\nusemtl base\n";
  const glm::dvec3 centre{0.0, kBoxHeight / 2, 0.0};
  const glm::dvec3 half{kBoxHalfWidth, kBoxHeight / 2, kBoxHalfWidth};
  // Corner index bits: x, y, z (set = positive side).
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 sign{(i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0};
    const glm::dvec3 p = centre + sign * half;
    append_vec(obj, "v", {p.x, p.y, p.z});
  }
  // One normal per face: the hard edges are the point of this part.
  std::string faces;
  for (int axis = 0; axis < 3; ++axis) {
    for (const double side : {1.0, -1.0}) {
      glm::dvec3 n(0.0);
      n[axis] = side;
      append_vec(obj, "vn", {n.x, n.y, n.z});
      const int normal_index = first_normal + axis * 2 + (side > 0 ? 0 : 1);
      // Tangents u, v with u x v = n make the corner order below
      // counter-clockwise seen from outside.
      glm::dvec3 u(0.0);
      glm::dvec3 v(0.0);
      u[side > 0 ? (axis + 1) % 3 : (axis + 2) % 3] = 1.0;
      v[side > 0 ? (axis + 2) % 3 : (axis + 1) % 3] = 1.0;
      faces += 'f';
      for (const auto& [su, sv] : {std::array<double, 2>{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
        const glm::dvec3 s = n + su * u + sv * v;
        const int index = (s.x > 0 ? 1 : 0) | (s.y > 0 ? 2 : 0) | (s.z > 0 ? 4 : 0);
        faces += ' ';
        faces += corner(first_position + index, 0, normal_index);
      }
      faces += '\n';
    }
  }
  obj += faces;
}

}  // namespace

Bundle make_demo_bundle() {
  std::string obj =
      "# toond demo model: a textured sphere on a hard-edged box, generated by toond\n"
      "mtllib demo.mtl\n";
  append_sphere(obj);
  const int sphere_positions = 2 + (kRings - 1) * kSegments;
  append_box(obj, sphere_positions + 1, sphere_positions + 1);

  const std::string mtl =
      "# toond demo materials\n"
      "newmtl body\n"
      "Kd 1.000000 1.000000 1.000000\n"
      "map_Kd textures/demo.png\n"
      "\n"
      "newmtl base\n"
      "Kd 0.180000 0.420000 0.650000\n";

  Bundle bundle;
  bundle.add("demo.obj", std::move(obj));
  bundle.add("demo.mtl", mtl);
  bundle.add("textures/demo.png", make_texture_png());
  // Not referenced by the MTL: files a request may name.
  bundle.add("ramps/sharp.png", make_ramp_png());
  bundle.add("textures/floor.png", make_floor_png());
  return bundle;
}

}  // namespace toond::scene
