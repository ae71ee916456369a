#include "support/costly_models.h"

#include <cmath>

#include "support/heavy_inputs.h"

namespace toond::test {
namespace {

std::string vertex(double x, double y, double z) { return obj_vertex_line(x, y, z); }

// A face of the three vertices written last (relative indices).
const char* kLastTriangle = "f -3 -2 -1\n";

}  // namespace

std::string nearly_coincident_triangles(int n) {
  std::string obj = "# nearly coincident triangles\n";
  for (int i = 0; i < n; ++i) {
    const double z = 1e-6 * i;
    obj += vertex(-1, -1, z) + vertex(1, -1, z) + vertex(-1, 1, z) + kLastTriangle;
  }
  return obj;
}

std::string one_triangle_many_materials(int n) {
  std::string obj = "# one triangle under many material names\n";
  for (int i = 0; i < n; ++i) {
    obj += "usemtl m" + std::to_string(i) + "\n";
    obj += vertex(-1, -1, 0) + vertex(1, -1, 0) + vertex(-1, 1, 0) + kLastTriangle;
  }
  return obj;
}

std::string stacked_triangles(int n) {
  std::string obj = "# stacked distinct triangles\n";
  for (int i = 0; i < n; ++i) {
    const double z = static_cast<double>(i) / n;
    const double turn = 0.01 * i;
    const double c = std::cos(turn);
    const double s = std::sin(turn);
    // A triangle that holds the unit square, turned about the view axis.
    const auto corner = [&](double x, double y) { return vertex(x * c - y * s, x * s + y * c, z); };
    obj += corner(-1.5, -1.5) + corner(3, -1.5) + corner(-1.5, 3) + kLastTriangle;
  }
  return obj;
}

std::string crossing_slivers(int n) {
  std::string obj = "# slivers crossing the frame\n";
  for (int i = 0; i < n; ++i) {
    const double t = static_cast<double>(i) / n;
    // From the bottom left to the top right, each shifted along the other
    // diagonal so that together they sweep the square.
    const double shift = 2.0 * t - 1.0;
    obj += vertex(-1 + shift, -1 - shift, 0) + vertex(1 + shift, 1 - shift, 0) +
           vertex(1 + shift + 1e-4, 1 - shift, 0) + kLastTriangle;
  }
  return obj;
}

const std::vector<CostlyModel>& costly_models() {
  static const std::vector<CostlyModel> models = {
      {"nearly_coincident", "large nearly coincident triangles", nearly_coincident_triangles, 60000},
      {"one_triangle_many_materials", "one triangle repeated under new material names", one_triangle_many_materials,
       100000},
      {"stacked", "distinct large triangles stacked", stacked_triangles, 20000},
      // 60,000 rather than the bench's 200,000: the simplifier's work on
      // slivers makes a larger import outlast --max-import-seconds under
      // the sanitizers.
      {"crossing_slivers", "thin slivers crossing the frame", crossing_slivers, 60000},
  };
  return models;
}

}  // namespace toond::test
