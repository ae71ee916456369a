// toond's half of the rig conformance suite (tests/conformance/): imports a
// model through toond's own import path (scene::import_bundle, which runs
// the assimp helper for FBX and COLLADA), poses it with scene/animation/pose.h as
// the daemon does (clip_time, pose_nodes, pose_vertices) at the times
// given, and writes JSON: every vertex at rest and in each pose, in the
// file's world space, and for each pose how far each level of detail's
// posed surface is from the full posed mesh.
//
//   toond-pose-dump --clip NAME --times T[,T...] MODEL_FILE [OTHER_FILE...]
//
// The bundle holds MODEL_FILE and the other files (a .gltf's .bin) by
// their file names. --clip takes the name as the file gives it or its
// index in the file.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "scene/animation/clip_sampling.h"
#include "scene/animation/pose.h"
#include "scene/import/bundle_import.h"
#include "scene/reading/import_error.h"
#include "support/surface_distance.h"

namespace toond::conformance {
namespace {

struct Options {
  std::string clip;
  std::vector<double> times;
  std::vector<std::filesystem::path> files;
};

[[noreturn]] void usage(const std::string& why) {
  std::cerr << "toond-pose-dump: " << why
            << "\nusage: toond-pose-dump --clip NAME --times T[,T...] MODEL_FILE [OTHER_FILE...]\n";
  std::exit(2);
}

std::vector<double> parse_times(const std::string& list) {
  std::vector<double> times;
  std::istringstream in(list);
  for (std::string item; std::getline(in, item, ',');) {
    double t = 0;
    const auto [end, error] = std::from_chars(item.data(), item.data() + item.size(), t);
    if (error != std::errc() || end != item.data() + item.size()) usage("not a time: '" + item + "'");
    times.push_back(t);
  }
  return times;
}

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if ((arg == "--clip" || arg == "--times") && i + 1 >= argc) usage(arg + " needs a value");
    if (arg == "--clip") {
      options.clip = argv[++i];
    } else if (arg == "--times") {
      options.times = parse_times(argv[++i]);
    } else if (arg.starts_with("--")) {
      usage("unknown option " + arg);
    } else {
      options.files.emplace_back(arg);
    }
  }
  if (options.files.empty()) usage("no model file");
  if (options.clip.empty()) usage("no --clip");
  return options;
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) usage("cannot read " + path.string());
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

std::size_t find_clip(const scene::Rig& rig, const std::string& name) {
  if (const auto found = rig.find_clip(name)) return *found;
  std::size_t index = 0;
  const auto [end, error] = std::from_chars(name.data(), name.data() + name.size(), index);
  if (error == std::errc() && end == name.data() + name.size() && index < rig.clips.size()) return index;
  std::cerr << "toond-pose-dump: no clip '" << name << "'; the clips are " << rig.clip_names() << "\n";
  std::exit(1);
}

// The largest singular value of a joint matrix's linear part: how much the
// joint can stretch a distance. Worked out here again on purpose, apart
// from scene::largest_joint_stretch (which the renderer scales a level's
// error by), so a wrong bound there cannot also pass here. The square root of the largest eigenvalue
// of MᵀM, a symmetric 3×3 matrix, by the closed form for its roots.
double stretch_of(const glm::mat4& joint) {
  const glm::dmat3 m(joint);
  const glm::dmat3 a = glm::transpose(m) * m;
  const double p1 = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
  const double q = (a[0][0] + a[1][1] + a[2][2]) / 3.0;
  const double p2 =
      (a[0][0] - q) * (a[0][0] - q) + (a[1][1] - q) * (a[1][1] - q) + (a[2][2] - q) * (a[2][2] - q) + 2 * p1;
  if (!(p2 > 1e-300)) return std::sqrt(std::max(q, 0.0));
  const double p = std::sqrt(p2 / 6.0);
  const double r = std::clamp(glm::determinant((a - q * glm::dmat3(1.0)) / p) / 2.0, -1.0, 1.0);
  return std::sqrt(std::max(q + 2.0 * p * std::cos(std::acos(r) / 3.0), 0.0));
}

double largest_stretch(const scene::SkinPose& pose) {
  double largest = 0;
  for (const glm::mat4& joint : pose.joints) largest = std::max(largest, stretch_of(joint));
  return largest;
}

nlohmann::json flat(const std::vector<glm::dvec3>& points) {
  nlohmann::json out = nlohmann::json::array();
  for (const glm::dvec3& p : points) {
    out.push_back(p.x);
    out.push_back(p.y);
    out.push_back(p.z);
  }
  return out;
}

// Posed positions are floats: a vertex the simplifier left exactly on a
// level's triangle (a ring of a straight tube between two rings kept) is
// found up to a few float roundings of the model's size off it (7e-9 of a
// 2 m bar here). This much of the size is allowed beyond a level's bound
// for that rounding alone.
constexpr double kFloatRounding = 1e-6;

// Each level's posed triangles against the full posed mesh: the farthest
// any full-detail vertex is from the level's surface, beside the level's
// own error (mesh units, measured at rest) times the pose's largest joint
// stretch, plus float rounding.
nlohmann::json level_distances(const scene::Mesh& mesh, const std::vector<glm::dvec3>& posed, double stretch) {
  const double rounding = kFloatRounding * glm::length(glm::dvec3(mesh.bounds.max - mesh.bounds.min));
  nlohmann::json levels = nlohmann::json::array();
  for (std::size_t l = 0; l < mesh.lods.size(); ++l) {
    const scene::MeshLod& lod = mesh.lods[l];
    const test::SurfaceDistance surface(posed, lod.indices);
    double farthest = 0;
    std::size_t beyond = 0;
    const double bound = lod.error * stretch + rounding;
    for (const glm::dvec3& p : posed) {
      const double d = surface.distance(p);
      farthest = std::max(farthest, d);
      if (d > bound) ++beyond;
    }
    levels.push_back({{"level", l + 1},
                      {"triangles", lod.triangle_count()},
                      {"error", lod.error},
                      {"bound", bound},
                      {"farthest", farthest},
                      {"vertices_beyond", beyond}});
  }
  return levels;
}

int run(const Options& options) {
  scene::Bundle bundle;
  for (const std::filesystem::path& file : options.files) bundle.add(file.filename().string(), read_file(file));
  const scene::Model model = scene::import_bundle(bundle);
  if (!model.rig) {
    std::cerr << "toond-pose-dump: " << options.files.front() << " has nothing that moves\n";
    return 1;
  }
  const scene::Rig& rig = *model.rig;
  const scene::Mesh& mesh = model.mesh;
  const std::size_t clip_index = find_clip(rig, options.clip);
  const scene::Clip& clip = rig.clips[clip_index];
  const glm::dmat4 mesh_to_file = glm::inverse(rig.file_to_mesh);
  const auto in_file = [&](const std::vector<glm::vec3>& positions) {
    std::vector<glm::dvec3> out;
    out.reserve(positions.size());
    for (const glm::vec3& p : positions) out.push_back(glm::dvec3(mesh_to_file * glm::dvec4(glm::dvec3(p), 1.0)));
    return out;
  };

  nlohmann::json out;
  out["file"] = options.files.front().filename().string();
  out["warnings"] = model.warnings;
  for (const scene::Clip& c : rig.clips) out["clips"].push_back({{"name", c.name}, {"duration", c.duration}});
  out["clip"] = {{"index", clip_index}, {"name", clip.name}, {"duration", clip.duration}};
  out["vertices"] = mesh.positions.size();
  out["triangles"] = mesh.triangle_count();
  for (std::size_t l = 0; l < mesh.lods.size(); ++l) {
    out["levels"].push_back(
        {{"level", l + 1}, {"triangles", mesh.lods[l].triangle_count()}, {"error", mesh.lods[l].error}});
  }
  out["rest"] = flat(in_file(mesh.positions));
  out["poses"] = nlohmann::json::array();
  for (const double time : options.times) {
    const double on_loop = scene::clip_time(clip, time);
    const scene::NodePose nodes = scene::pose_nodes(rig, &clip, on_loop);
    const scene::PosedVertices posed = scene::pose_vertices(mesh, rig, nodes);
    std::vector<glm::dvec3> in_mesh(posed.positions.begin(), posed.positions.end());
    const double stretch = largest_stretch(scene::skin_pose(mesh, rig, nodes));
    out["poses"].push_back({{"time", time},
                            {"clip_time", on_loop},
                            {"joint_stretch", stretch},
                            {"positions", flat(in_file(posed.positions))},
                            {"levels", level_distances(mesh, in_mesh, stretch)}});
  }
  std::cout << out.dump() << "\n";
  return 0;
}

}  // namespace
}  // namespace toond::conformance

int main(int argc, char** argv) {
  try {
    return toond::conformance::run(toond::conformance::parse(argc, argv));
  } catch (const std::exception& e) {
    std::cerr << "toond-pose-dump: " << e.what() << "\n";
    return 1;
  }
}
