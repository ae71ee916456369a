#pragma once
// The data layers (render output depth, normal, id) as PNG files: each
// turns a FloatImage (float_image.h) into the samples its kind stores and
// writes them with libpng. The background of every kind decodes to a value
// no covered pixel has.
#include <string>

#include "image/float_image.h"
#include "image/png_writer.h"

namespace toond::image {

// An id layer's indices are bytes, 0 the background.
inline constexpr int kMaxLayerIds = 255;

// The nearest and farthest depth of the covered pixels (along the view
// axis, scene units); both 0 when nothing is covered.
struct DepthRange {
  float near_depth = 0;
  float far_depth = 0;
};
DepthRange visible_depth_range(const FloatImage& layer);

// 16-bit grey: near_depth → 0, far_depth → 65534, linear in between;
// background 65535. `text` goes in tEXt chunks.
std::string encode_depth_png(const FloatImage& layer, const DepthRange& range, int compression_level,
                             const TextChunks& text);

// View-space normals as RGB (n·0.5 + 0.5, 8 bits a channel), alpha 255
// where covered; background all zero (transparent).
std::string encode_normal_png(const FloatImage& layer, int compression_level, const TextChunks& text);

// Colour type 3 with one palette entry per id: index 0 (transparent) for
// the background, 1 to `id_count` for what the layer's first channel
// holds, each a colour far from its neighbours' so the ids can be told
// apart by eye. At most kMaxLayerIds.
std::string encode_id_png(const FloatImage& layer, int id_count, int compression_level, const TextChunks& text);

}  // namespace toond::image
