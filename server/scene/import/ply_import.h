#pragma once
// PLY (Stanford polygon files), what scanners and MeshLab write: ASCII and
// binary of both byte orders. Read: vertex x/y/z; nx/ny/nz where present
// (else normals by angle, scene/mesh/normals_by_angle.h); texture coordinates as
// s/t, u/v or texture_u/texture_v; red/green/blue vertex colours (bytes or
// 0..1 reals) as the base colour; faces of any corner count (fanned) from
// vertex_indices or vertex_index. Other elements and properties are skipped
// and named in the warnings.
#include "scene/mesh/model.h"
#include "scene/reading/bundle.h"
#include "scene/reading/import_choices.h"
#include "scene/reading/import_limits.h"

namespace toond::scene {

// Reads the bundle's one .ply. A header over 64 KiB or without
// end_header, an unknown format or type, counts over `limits` (checked
// before anything is allocated) or larger than the bytes that follow can
// hold, data cut short, a face naming a vertex that does not exist, a bad
// number or a coordinate that is not finite is an ImportError naming the
// file.
Model import_ply_bundle(const Bundle& bundle, const ImportLimits& limits = {}, const ImportChoices& choices = {});

}  // namespace toond::scene
