#pragma once
// A triangle drawn again on top of itself adds nothing to the picture but
// its cost: a file that repeats one large face a hundred thousand times
// (under as many material names) makes every render cover the frame that
// often. Import keeps one of each.
#include <cstddef>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace toond::scene {

// Corners of one triangle, in the order the file winds them.
struct TriangleCorners {
  glm::dvec3 corner[3];
};

// Which triangles to keep: false for every triangle whose corners (by exact
// coordinates, -0 equal to +0) equal a later triangle's in some rotation of
// their order (a b c, b c a, c a b). The reverse order (a c b) is the other
// side of the face and is kept. Of a set of repeats the last one is kept:
// it is the one the depth test (less-or-equal) lets show when triangles
// are drawn in the order given. Linear in the count (one hash table).
std::vector<bool> last_of_each_triangle(std::span<const TriangleCorners> triangles);

}  // namespace toond::scene
