#pragma once
// Valid but heavy uploads, made here at any size: each construct a file can
// repeat or make large, so a test can import it at n and 2n and compare the
// times. Every bundle is accepted by the importer (some with warnings).
#include <functional>
#include <string>
#include <vector>

#include "scene/reading/bundle.h"

namespace toond::test {

struct HeavyInput {
  std::string name;  // a gtest-safe name: letters, digits, '_'
  std::string what;  // what the construct is, for failure messages
  // The bundle at size n; n is the count of whatever repeats.
  std::function<scene::Bundle(int n)> make;
  // A size at which the import takes long enough to time (tens of ms or
  // more on a 2-core machine) while the bundle stays within upload limits.
  int base_n = 0;
};

const std::vector<HeavyInput>& heavy_inputs();

// "v x y z\n" with every digit a double needs to come back the same.
std::string obj_vertex_line(double x, double y, double z);

}  // namespace toond::test
