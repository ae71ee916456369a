#include "support/heavy_inputs.h"

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "image/png_codec.h"
#include "support/mesh_file_writers.h"

namespace toond::test {
namespace {

std::string vertex_line(double x, double y, double z) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "v %.9g %.9g %.9g\n", x, y, z);
  return buf;
}

// n points on a circle, every other one pulled in: a star, so no vertex is
// trivially an ear and a triangulator must do real work.
std::string star_vertices(int n) {
  const double pi = std::acos(-1.0);
  std::string obj;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * pi * i / n;
    const double r = i % 2 == 0 ? 1.0 : 0.6;
    obj += vertex_line(r * std::cos(a), r * std::sin(a), 0.0);
  }
  return obj;
}

// A square grid of (g+1)² vertices in the XY plane, offset by z, with
// 1-based indices starting after `first`.
std::string grid(int g, double z, int first, std::string* faces) {
  std::string vertices;
  for (int y = 0; y <= g; ++y) {
    for (int x = 0; x <= g; ++x) vertices += vertex_line(double(x) / g, double(y) / g, z);
  }
  const auto at = [&](int x, int y) { return std::to_string(first + y * (g + 1) + x + 1); };
  for (int y = 0; y < g; ++y) {
    for (int x = 0; x < g; ++x) {
      *faces += "f " + at(x, y) + " " + at(x + 1, y) + " " + at(x + 1, y + 1) + " " + at(x, y + 1) + "\n";
    }
  }
  return vertices;
}

scene::Bundle obj_bundle(std::string obj) {
  scene::Bundle bundle;
  bundle.add("heavy.obj", std::move(obj));
  return bundle;
}

scene::Bundle huge_polygon(int n) {
  std::string face = "f";
  for (int i = 1; i <= n; ++i) face += " " + std::to_string(i);
  return obj_bundle(star_vertices(n) + face + "\n");
}

// Each `usemtl` names a material the file never defines, as the report
// that found this construct did; every switch is followed by a new triangle.
scene::Bundle material_switches(int n) {
  std::string obj = vertex_line(0, 0, 0);
  for (int i = 0; i <= n; ++i) obj += vertex_line(1, i, 0);
  for (int i = 0; i < n; ++i) {
    obj += "usemtl m" + std::to_string(i % 97) + "\nf 1 " + std::to_string(i + 2) + " " + std::to_string(i + 3) + "\n";
  }
  return obj_bundle(obj);
}

scene::Bundle group_switches(int n) {
  std::string obj = vertex_line(0, 0, 0);
  for (int i = 0; i <= n; ++i) obj += vertex_line(1, i, 0);
  for (int i = 0; i < n; ++i) {
    const std::string k = std::to_string(i);
    obj += "g g" + k + "\no o" + k + "\ns " + std::to_string(i % 31 + 1) + "\nf 1 " + std::to_string(i + 2) + " " +
           std::to_string(i + 3) + "\n";
  }
  return obj_bundle(obj);
}

// n materials in the MTL, each used by one triangle, all sharing one texture.
scene::Bundle many_materials_one_texture(int n) {
  std::string mtl;
  std::string obj = "mtllib heavy.mtl\n" + vertex_line(0, 0, 0);
  for (int i = 0; i <= n; ++i) obj += vertex_line(1, i, 0);
  obj += "vt 0 0\nvt 1 0\nvt 1 1\n";
  for (int i = 0; i < n; ++i) {
    const std::string name = "m" + std::to_string(i);
    mtl += "newmtl " + name + "\nKd 0.5 0.5 0.5\nmap_Kd skin.png\n";
    obj += "usemtl " + name + "\nf 1/1 " + std::to_string(i + 2) + "/2 " + std::to_string(i + 3) + "/3\n";
  }
  scene::Bundle bundle;
  bundle.add("heavy.obj", obj);
  bundle.add("heavy.mtl", mtl);
  image::Image texel;
  texel.width = texel.height = 1;
  texel.rgba = {128, 128, 128, 255};
  bundle.add("skin.png", image::encode_png(texel));
  return bundle;
}

// 40·n materials whose textures are missing, in a bundle of n other files
// (the file list is capped at 1000, so n stays below that): every failed
// look-up is also tried case-insensitively against the file list.
scene::Bundle missing_textures_many_files(int files) {
  const int n = 40 * files;
  scene::Bundle bundle;
  std::string mtl;
  std::string obj = "mtllib heavy.mtl\n" + vertex_line(0, 0, 0);
  for (int i = 0; i <= n; ++i) obj += vertex_line(1, i, 0);
  for (int i = 0; i < n; ++i) {
    const std::string name = "m" + std::to_string(i);
    mtl += "newmtl " + name + "\nmap_Kd missing" + std::to_string(i) + ".png\n";
    obj += "usemtl " + name + "\nf 1 " + std::to_string(i + 2) + " " + std::to_string(i + 3) + "\n";
  }
  for (int i = 0; i < files; ++i) bundle.add("notes/n" + std::to_string(i) + ".txt", "x");
  bundle.add("heavy.obj", obj);
  bundle.add("heavy.mtl", mtl);
  return bundle;
}

// One vertex written with n digits, and a comment line n bytes long.
scene::Bundle long_lines(int n) {
  std::string obj = "# " + std::string(static_cast<std::size_t>(n), 'x') + "\n";
  obj += "v 0." + std::string(static_cast<std::size_t>(n), '1') + " 0 0\n";
  obj += "v 1 0 0\nv 0 1 0\nf 1 2 3\n";
  return obj_bundle(obj);
}

// A polygon that names the same three vertices over and over.
scene::Bundle repeated_corners(int n) {
  std::string face = "f";
  for (int i = 0; i < n; ++i) face += " " + std::to_string(i % 3 + 1);
  return obj_bundle("v 0 0 0\nv 1 0 0\nv 0 1 0\n" + face + "\n");
}

scene::Bundle repeated_triangle(int n) {
  std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  for (int i = 0; i < n; ++i) obj += "f 1 2 3\n";
  return obj_bundle(obj);
}

// n triangles on one edge, each with its own third vertex around it.
scene::Bundle edge_fan(int n) {
  const double pi = std::acos(-1.0);
  std::string obj = "v 0 0 -1\nv 0 0 1\n";
  std::string faces;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * pi * i / n;
    obj += vertex_line(std::cos(a), std::sin(a), 0.0);
    faces += "f 1 2 " + std::to_string(i + 3) + "\n";
  }
  return obj_bundle(obj + faces);
}

// n copies of one 16×16 grid at the same place, each with its own vertices:
// they weld into one sheet that n faces share per edge.
scene::Bundle coincident_sheets(int n) {
  constexpr int g = 16;
  std::string vertices;
  std::string faces;
  for (int k = 0; k < n; ++k) vertices += grid(g, 0.0, k * (g + 1) * (g + 1), &faces);
  return obj_bundle(vertices + faces);
}

scene::Bundle m_bundle(std::string text) {
  scene::Bundle bundle;
  bundle.add("heavy.m", std::move(text));
  return bundle;
}

scene::Bundle m_repeated_triangle(int n) {
  std::string m = "Vertex 1 0 0 0\nVertex 2 1 0 0\nVertex 3 0 1 0\n";
  for (int i = 0; i < n; ++i) m += "Face " + std::to_string(i + 1) + " 1 2 3\n";
  return m_bundle(m);
}

scene::Bundle m_edge_fan(int n) {
  const double pi = std::acos(-1.0);
  std::string m = "Vertex 1 0 0 -1\nVertex 2 0 0 1\n";
  std::string faces;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * pi * i / n;
    char buf[96];
    std::snprintf(buf, sizeof buf, "Vertex %d %.9g %.9g 0\n", i + 3, std::cos(a), std::sin(a));
    m += buf;
    faces += "Face " + std::to_string(i + 1) + " 1 2 " + std::to_string(i + 3) + "\n";
  }
  return m_bundle(m + faces);
}

}  // namespace

// A strip of 100 × n quads as binary STL, and as binary PLY: positions
// written once per corner (STL) or shared (PLY), both shaded by angle.
scene::Bundle stl_strip(int n) {
  scene::Bundle bundle;
  bundle.add("strip.stl", binary_stl(wavy_grid(100, n)));
  return bundle;
}

scene::Bundle ply_strip(int n) {
  scene::Bundle bundle;
  bundle.add("strip.ply", ply(wavy_grid(100, n), PlyForm::BinaryLittle));
  return bundle;
}

namespace {

// A .glb of `json` and its binary chunk.
std::string glb(const nlohmann::json& json, std::string bin) {
  std::string text = json.dump();
  while (text.size() % 4 != 0) text.push_back(' ');
  while (bin.size() % 4 != 0) bin.push_back('\0');
  std::string out;
  const auto u32 = [&](std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
  u32(0x46546C67);
  u32(2);
  u32(static_cast<std::uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
  u32(static_cast<std::uint32_t>(text.size()));
  u32(0x4E4F534A);
  out += text;
  u32(static_cast<std::uint32_t>(bin.size()));
  u32(0x004E4942);
  return out + bin;
}

}  // namespace

// A skinned bar of 10n joints in one chain (a ring of four vertices per
// joint) and a clip turning every joint, 100 keys each: 1,000 joints and
// 100,000 keys at n = 100.
scene::Bundle skinned_chain(int n) {
  const int joints = 10 * n;
  constexpr int kKeys = 100;
  nlohmann::json j = {{"asset", {{"version", "2.0"}}}, {"scene", 0}};
  std::string bin;
  const auto accessor = [&](const void* data, std::size_t bytes, std::size_t count, int component, const char* type) {
    j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes}});
    bin.append(static_cast<const char*>(data), bytes);
    j["accessors"].push_back(
        {{"bufferView", j["bufferViews"].size() - 1}, {"componentType", component}, {"count", count}, {"type", type}});
    return j["accessors"].size() - 1;
  };
  std::vector<float> positions;
  std::vector<std::uint16_t> joint_of;
  std::vector<float> weights;
  std::vector<std::uint32_t> indices;
  for (int r = 0; r < joints; ++r) {
    for (const auto& [x, z] : {std::pair{-0.2f, -0.2f}, {0.2f, -0.2f}, {0.2f, 0.2f}, {-0.2f, 0.2f}}) {
      positions.insert(positions.end(), {x, static_cast<float>(r), z});
      joint_of.insert(joint_of.end(), {static_cast<std::uint16_t>(r), 0, 0, 0});
      weights.insert(weights.end(), {1, 0, 0, 0});
    }
    for (std::uint32_t k = 0; r + 1 < joints && k < 4; ++k) {
      const std::uint32_t a = static_cast<std::uint32_t>(r) * 4 + k,
                          b = static_cast<std::uint32_t>(r) * 4 + (k + 1) % 4;
      indices.insert(indices.end(), {a, b + 4, b, a, a + 4, b + 4});
    }
  }
  nlohmann::json attributes = {
      {"POSITION", accessor(positions.data(), positions.size() * 4, positions.size() / 3, 5126, "VEC3")},
      {"JOINTS_0", accessor(joint_of.data(), joint_of.size() * 2, joint_of.size() / 4, 5123, "VEC4")},
      {"WEIGHTS_0", accessor(weights.data(), weights.size() * 4, weights.size() / 4, 5126, "VEC4")}};
  const auto index = accessor(indices.data(), indices.size() * 4, indices.size(), 5125, "SCALAR");
  j["meshes"] = {{{"primitives", {{{"attributes", attributes}, {"indices", index}}}}}};
  j["nodes"] = {{{"mesh", 0}, {"skin", 0}}};
  std::vector<int> joint_nodes;
  std::vector<float> inverse_binds;
  for (int r = 0; r < joints; ++r) {
    nlohmann::json node = {{"translation", {0, r == 0 ? 0 : 1, 0}}};
    if (r + 1 < joints) node["children"] = {r + 2};
    j["nodes"].push_back(node);
    joint_nodes.push_back(r + 1);
    inverse_binds.insert(inverse_binds.end(), {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, -static_cast<float>(r), 0, 1});
  }
  j["scenes"] = {{{"nodes", {0, 1}}}};
  j["skins"] = {
      {{"joints", joint_nodes},
       {"inverseBindMatrices", accessor(inverse_binds.data(), inverse_binds.size() * 4, joints, 5126, "MAT4")}}};
  std::vector<float> times(kKeys);
  for (int k = 0; k < kKeys; ++k) times[static_cast<std::size_t>(k)] = 0.04f * static_cast<float>(k);
  const auto input = accessor(times.data(), times.size() * 4, times.size(), 5126, "SCALAR");
  nlohmann::json samplers = nlohmann::json::array(), channels = nlohmann::json::array();
  for (int r = 0; r < joints; ++r) {
    std::vector<float> turns;
    for (int k = 0; k < kKeys; ++k) {
      const float half = 0.01f * std::sin(0.3f * static_cast<float>(k + r));
      turns.insert(turns.end(), {0, 0, std::sin(half), std::cos(half)});
    }
    samplers.push_back({{"input", input}, {"output", accessor(turns.data(), turns.size() * 4, kKeys, 5126, "VEC4")}});
    channels.push_back({{"sampler", r}, {"target", {{"node", r + 1}, {"path", "rotation"}}}});
  }
  j["animations"] = {{{"name", "wave"}, {"samplers", samplers}, {"channels", channels}}};
  j["buffers"] = {{{"byteLength", bin.size()}}};
  scene::Bundle bundle;
  bundle.add("chain.glb", glb(j, bin));
  return bundle;
}

std::string obj_vertex_line(double x, double y, double z) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "v %.17g %.17g %.17g\n", x, y, z);
  return buf;
}

const std::vector<HeavyInput>& heavy_inputs() {
  static const std::vector<HeavyInput> inputs = {
      {"huge_polygon", "one star-shaped polygon of n vertices", huge_polygon, 20000},
      {"material_switches", "n usemtl switches to undefined materials, a triangle after each", material_switches,
       40000},
      {"group_switches", "n g/o/s switches, a triangle after each", group_switches, 40000},
      {"many_materials", "n materials in the MTL sharing one texture, each used once", many_materials_one_texture,
       20000},
      {"missing_textures", "40n materials with missing textures beside n other files", missing_textures_many_files,
       120},
      {"long_lines", "a number with n digits and a comment n bytes long", long_lines, 4000000},
      {"repeated_corners", "one polygon naming the same three vertices n times", repeated_corners, 40000},
      {"repeated_triangle", "the same triangle n times", repeated_triangle, 40000},
      {"edge_fan", "n triangles sharing one edge", edge_fan, 40000},
      {"coincident_sheets", "n copies of a 16x16 grid at one place", coincident_sheets, 100},
      {"m_repeated_triangle", ".m: the same triangle n times", m_repeated_triangle, 40000},
      {"m_edge_fan", ".m: n triangles sharing one edge", m_edge_fan, 40000},
      {"stl_strip", "binary STL: a strip of 100 × n quads", stl_strip, 60},
      {"ply_strip", "binary PLY: a strip of 100 × n quads", ply_strip, 60},
      {"skinned_chain", "glTF: 10n joints in a chain skinning a bar, a clip of 1000n keys", skinned_chain, 100},
  };
  return inputs;
}

}  // namespace toond::test
