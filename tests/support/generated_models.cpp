#include "support/generated_models.h"

#include <cmath>
#include <cstdint>
#include <cstdio>

namespace toond::test {
namespace {

std::string vec_line(const char* tag, glm::dvec3 v) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "%s %.17g %.17g %.17g\n", tag, v.x, v.y, v.z);
  return buf;
}

}  // namespace

std::string sphere_obj(int segments, int rings, double radius, glm::dvec3 centre) {
  const double pi = std::acos(-1.0);
  std::string obj = "# UV sphere\n";
  // Ring 0 is the north pole, ring `rings` the south pole; each ring holds
  // segments + 1 vertices so the seam has its own copies.
  // The seam's copies and the poles are written with exactly the same
  // coordinates, as an exporter sharing one `v` would (sin 2π and sin π are
  // not 0 in floating point).
  for (int r = 0; r <= rings; ++r) {
    const double theta = pi * r / rings;
    const double ring_radius = r == 0 || r == rings ? 0.0 : std::sin(theta);
    for (int s = 0; s <= segments; ++s) {
      const double phi = s == segments ? 0.0 : 2.0 * pi * s / segments;
      const glm::dvec3 n(ring_radius * std::cos(phi), std::cos(theta), -ring_radius * std::sin(phi));
      obj += vec_line("v", centre + n * radius);
      obj += vec_line("vn", n);
    }
  }
  auto index = [&](int r, int s) { return r * (segments + 1) + s + 1; };
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const int a = index(r, s), b = index(r + 1, s), c = index(r + 1, s + 1), d = index(r, s + 1);
      if (r != 0)
        obj += "f " + std::to_string(a) + "//" + std::to_string(a) + " " + std::to_string(b) + "//" +
               std::to_string(b) + " " + std::to_string(d) + "//" + std::to_string(d) + "\n";
      if (r != rings - 1)
        obj += "f " + std::to_string(b) + "//" + std::to_string(b) + " " + std::to_string(c) + "//" +
               std::to_string(c) + " " + std::to_string(d) + "//" + std::to_string(d) + "\n";
    }
  }
  return obj;
}

std::string cube_obj(double h, glm::dvec3 c) {
  std::string obj = "# cube with one normal per face\n";
  for (int i = 0; i < 8; ++i) {
    obj += vec_line("v", c + glm::dvec3(i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h));
  }
  obj += "vn -1 0 0\nvn 1 0 0\nvn 0 -1 0\nvn 0 1 0\nvn 0 0 -1\nvn 0 0 1\n";
  // Corners are numbered by their bits (x = 1, y = 2, z = 4), 1-based.
  obj += "f 1//1 5//1 7//1 3//1\n";  // -x
  obj += "f 2//2 4//2 8//2 6//2\n";  // +x
  obj += "f 1//3 2//3 6//3 5//3\n";  // -y
  obj += "f 3//4 7//4 8//4 4//4\n";  // +y
  obj += "f 1//5 3//5 4//5 2//5\n";  // -z
  obj += "f 5//6 6//6 8//6 7//6\n";  // +z
  return obj;
}

std::string disk_obj(int segments, double radius) {
  const double pi = std::acos(-1.0);
  std::string obj = "# flat disk facing +Z\nvn 0 0 1\n";
  obj += vec_line("v", glm::dvec3(0.0));
  for (int s = 0; s < segments; ++s) {
    const double phi = 2.0 * pi * s / segments;
    obj += vec_line("v", glm::dvec3(std::cos(phi), std::sin(phi), 0.0) * radius);
  }
  for (int s = 0; s < segments; ++s) {
    const int a = 2 + s, b = 2 + (s + 1) % segments;
    obj += "f 1//1 " + std::to_string(a) + "//1 " + std::to_string(b) + "//1\n";
  }
  return obj;
}

std::string bowl_obj(int segments, int rings) {
  const double pi = std::acos(-1.0);
  std::string obj = "# bowl: the lower half of a unit sphere\n";
  for (int r = 0; r <= rings; ++r) {
    const double polar = 0.5 * pi * (1.0 + static_cast<double>(r) / rings);  // the rim to the bottom pole
    for (int s = 0; s < segments; ++s) {
      const double around = 2.0 * pi * s / segments;
      const glm::dvec3 p(std::sin(polar) * std::cos(around), std::cos(polar), std::sin(polar) * std::sin(around));
      obj += vec_line("v", p);
      obj += vec_line("vn", p);
    }
  }
  const auto at = [&](int r, int s) { return std::to_string(r * segments + s % segments + 1); };
  const auto corner = [](const std::string& i) { return i + "//" + i; };
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const std::string a = at(r, s), b = at(r, s + 1), c = at(r + 1, s + 1), d = at(r + 1, s);
      obj += "f " + corner(a) + " " + corner(b) + " " + corner(c) + "\n";
      obj += "f " + corner(a) + " " + corner(c) + " " + corner(d) + "\n";
    }
  }
  return obj;
}

std::string exporter_sphere_obj(const ExporterSphere& sphere) {
  const double pi = std::acos(-1.0);
  const int segments = sphere.segments;
  const int rings = sphere.rings;
  std::string obj = "# UV sphere, exporter style\n";
  // A fixed sequence in [-1, 1): the same file on every run.
  std::uint32_t state = 12345u;
  auto scatter = [&] {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / static_cast<double>(1u << 23) - 1.0;
  };
  auto index = [&](int r, int s) { return r * (segments + 1) + s + 1; };
  for (int r = 0; r <= rings; ++r) {
    const double theta = pi * r / rings;
    for (int s = 0; s <= segments; ++s) {
      const double phi = 2.0 * pi * s / segments;
      const glm::dvec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
      glm::dvec3 p = n;
      const bool copy = r == 0 || r == rings || s == 0 || s == segments;
      if (copy && sphere.jitter > 0.0) p += glm::dvec3(scatter(), scatter(), scatter()) * sphere.jitter;
      obj += vec_line("v", p);
      if (sphere.normals == ExporterSphere::Normals::Smooth) obj += vec_line("vn", n);
      char vt[96];
      std::snprintf(vt, sizeof vt, "vt %.17g %.17g\n", static_cast<double>(s) / segments,
                    1.0 - static_cast<double>(r) / rings);
      obj += vt;
    }
  }
  int face_normal = 0;
  auto face = [&](int a, int b, int c) {
    std::string line = "f";
    if (sphere.normals == ExporterSphere::Normals::PerFace) {
      // The flat normal of this triangle, from its own corners.
      ++face_normal;
      const auto corner = [&](int i) {
        const int r = (i - 1) / (segments + 1), s = (i - 1) % (segments + 1);
        const double theta = pi * r / rings, phi = 2.0 * pi * s / segments;
        return glm::dvec3(std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi));
      };
      obj += vec_line("vn", glm::normalize(glm::cross(corner(b) - corner(a), corner(c) - corner(a))));
    }
    for (const int i : {a, b, c}) {
      line += " " + std::to_string(i) + "/" + std::to_string(i);
      if (sphere.normals == ExporterSphere::Normals::Smooth) line += "/" + std::to_string(i);
      if (sphere.normals == ExporterSphere::Normals::PerFace) line += "/" + std::to_string(face_normal);
    }
    obj += line + "\n";
  };
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const int a = index(r, s), b = index(r + 1, s), c = index(r + 1, s + 1), d = index(r, s + 1);
      if (r != 0) face(a, b, d);
      if (r != rings - 1) face(b, c, d);
    }
  }
  return obj;
}

}  // namespace toond::test
