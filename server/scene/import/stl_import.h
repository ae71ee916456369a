#pragma once
// STL, what CAD programs and 3D printers exchange: binary (an 80-byte
// header, a triangle count, 50 bytes a triangle) or ASCII (solid / facet /
// outer loop / vertex lines). Positions and triangles only: a facet's
// normal is ignored (exporters write zeros, or the winding's normal), so
// the mesh is shaded by angle (scene/mesh/normals_by_angle.h). Corners at the
// same coordinates become one position, so the triangles share edges.
#include "scene/mesh/model.h"
#include "scene/reading/bundle.h"
#include "scene/reading/import_choices.h"
#include "scene/reading/import_limits.h"

namespace toond::scene {

// Reads the bundle's one .stl. A file whose size is 84 + 50 × its count is
// binary even when its header starts with "solid" (many exporters write
// that); one that is neither that nor ASCII STL, a count that does not
// match the size, more triangles than `limits` allow (checked before
// anything is allocated), a bad number or a coordinate that is not finite
// is an ImportError naming the file.
Model import_stl_bundle(const Bundle& bundle, const ImportLimits& limits = {}, const ImportChoices& choices = {});

}  // namespace toond::scene
