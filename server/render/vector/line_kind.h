#pragma once
// The kinds of line a drawing holds, one layer each (the SVG's `<g id>`).
#include <array>
#include <cstdint>

namespace toond::render::vector {

enum class LineKind : std::uint8_t {
  Silhouette,    // where a face turned toward the eye meets one turned away
  Crease,        // a crease edge (scene/mesh/crease_edges.h) between two faces turned alike
  Intersection,  // a seam where parts cross (scene/mesh/intersection_lines.h)
  Boundary,      // an open edge, which one face alone borders
};
inline constexpr std::size_t kLineKinds = 4;
inline constexpr std::array<LineKind, kLineKinds> kAllLineKinds{LineKind::Silhouette, LineKind::Crease,
                                                                LineKind::Intersection, LineKind::Boundary};

// The layer's id in the SVG: silhouette, creases, intersections, boundary.
const char* layer_id(LineKind kind);

}  // namespace toond::render::vector
