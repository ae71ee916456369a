#pragma once
// Small uploads that are costly to draw: each construct covers the frame
// many times over (or crosses it with many thin triangles), the files a
// render service must price before drawing them. OBJ text, written here at
// any size n.
#include <string>
#include <vector>

namespace toond::test {

struct CostlyModel {
  std::string name;  // gtest-safe
  std::string what;  // for failure messages
  std::string (*obj)(int n);
  // A size at which one render at 512² takes llvmpipe seconds or more
  // unpriced (for the first two, the sizes of the reports).
  int pathological_n = 0;
};

// n large triangles, each filling the bounds, nearly coincident (each a
// hair, 1e-6 of the size, in front of the last): not repeats, so import
// keeps them all.
std::string nearly_coincident_triangles(int n);
// One triangle written n times, each time with new vertex lines and under
// another material name: import keeps one.
std::string one_triangle_many_materials(int n);
// n distinct large triangles stacked along the view axis, each turned a
// little: a deep stack of different faces.
std::string stacked_triangles(int n);
// n slivers, each crossing the whole bounds diagonally but only 1e-4 of it
// wide: little area, many screen tiles crossed.
std::string crossing_slivers(int n);

const std::vector<CostlyModel>& costly_models();

}  // namespace toond::test
