#include "render/vector/line_kind.h"

namespace toond::render::vector {

const char* layer_id(LineKind kind) {
  switch (kind) {
    case LineKind::Silhouette:
      return "silhouette";
    case LineKind::Crease:
      return "creases";
    case LineKind::Intersection:
      return "intersections";
    case LineKind::Boundary:
      return "boundary";
  }
  return "?";
}

}  // namespace toond::render::vector
