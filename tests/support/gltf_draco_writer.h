#pragma once
// Writes glTF primitives compressed with KHR_draco_mesh_compression, using
// Draco's own encoder, so tests can make what Draco exporters make without
// their tools.
#include "support/gltf_writer.h"

namespace toond::test {

struct DracoOptions {
  int quantization_bits = 0;  // for every attribute; 0 keeps the values exactly
  // Keep the accessors' buffer views as the uncompressed fallback (the
  // extension is then only used, not required). Filled with `fallback_fill`
  // bytes instead of the real data, so a reader that took the fallback over
  // the Draco data would show it.
  bool keep_fallback = false;
  char fallback_fill = '\0';
};

// `plain` (as build_gltf makes it: float attributes, 32-bit indices) with
// every indexed triangle-list primitive compressed: the Draco bytes go to a
// new view of buffer 0, and the primitive's accessors take their counts
// from the decoded mesh (Draco may split vertices), as the extension asks of
// writers.
GltfParts draco_compress(const GltfParts& plain, const DracoOptions& options = {});

}  // namespace toond::test
