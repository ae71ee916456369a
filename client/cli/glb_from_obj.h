#pragma once
// An OBJ bundle written as one binary glTF. The gallery shows a glTF model,
// and every shared model is an OBJ: toon writes one of them as a .glb at
// gallery time rather than the repository carrying a model file.
#include <string>

#include "bundle_scan.h"

namespace toond::cli {

// The .glb of a scanned OBJ bundle (scan.files.front() is the OBJ; its MTL
// files and textures follow, as scan_obj_bundle finds them). Polygons are cut
// into triangles as toond cuts the OBJ's. One primitive per material, with a
// vertex per distinct position/UV/normal corner: POSITION, NORMAL only where
// every corner of the primitive has a normal (otherwise toond computes them,
// as it would for the OBJ), TEXCOORD_0 likewise (v flipped: glTF's runs down
// the image). The MTL files are read by the daemon's own reader
// (obj_text/mtl_material.h): a material's Kd becomes its baseColorFactor, its
// map_Kd file an image inside the .glb, d (or Tr) below 1 the factor's alpha
// with alphaMode BLEND, and Ks 0 0 0 or illum 0/1 (no highlight) roughness 1;
// without Kd the factor is what toond gives such an MTL material (white with
// a texture, the plain grey without), and faces with no material get the
// grey toond draws them in, so the .glb renders as its OBJ does. Vertex
// colours, other MTL statements and smoothing groups are not carried. Throws
// UsageError when the OBJ does not parse, names a missing vertex or has no
// faces.
std::string glb_from_obj(const BundleScan& scan);

}  // namespace toond::cli
