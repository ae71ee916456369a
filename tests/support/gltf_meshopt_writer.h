#pragma once
// Writes glTF buffer views compressed with EXT_meshopt_compression, using
// meshoptimizer's own encoders, so tests can make what gltfpack makes
// without gltfpack.
#include <cstddef>
#include <string>

#include "support/gltf_writer.h"

namespace toond::test {

// What the buffer that the compressed views point into (their "fallback")
// holds.
enum class MeshoptFallback {
  StandIn,          // no URI, tagged "fallback": true; the extension is required (gltfpack's output)
  UntaggedStandIn,  // no URI and no tag; the extension is required
  Zeros,            // a data: URI of zero bytes, untagged; the extension is only used, so a
                    // reader that took the fallback would see every vertex at the origin
};

// `plain` (as build_gltf makes it) with every buffer view that a mesh
// accessor reads compressed: vertex attributes in ATTRIBUTES mode, a
// triangle list's indices in TRIANGLES mode, other indices in INDICES mode.
// The streams go to buffer 0 (the GLB's binary chunk or model.bin), with
// the views that stay uncompressed (images); the compressed views lie in
// buffer 1, the fallback.
GltfParts meshopt_compress(const GltfParts& plain, MeshoptFallback fallback = MeshoptFallback::StandIn);

// Adds to `parts` a view of `count` elements of `stride` bytes stored as a
// stream of `mode` ("ATTRIBUTES", "TRIANGLES", "INDICES") with `filter`:
// `elements` are what the stream encodes (already filter-encoded, e.g. by
// meshopt_encodeFilterOct, when `filter` is not "NONE"). The stream is
// appended to buffer 0 and the view lies in buffer 1, a stand-in without
// data that is added when missing. Returns the view's index.
int add_meshopt_view(GltfParts& parts, const void* elements, std::size_t count, std::size_t stride,
                     const std::string& mode, const std::string& filter = "NONE");

}  // namespace toond::test
