#include "sheet_files/aseprite_file.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

#include "sheet_files/atlas_view.h"
#include "sheet_files/byte_writer.h"
#include "sheet_files/tile_trim.h"

namespace toond::sheet_files {
namespace {

constexpr std::uint16_t kFileMagic = 0xA5E0;
constexpr std::uint16_t kFrameMagic = 0xF1FA;
constexpr std::uint16_t kLayerChunk = 0x2004;
constexpr std::uint16_t kCelChunk = 0x2005;
constexpr std::uint16_t kColorProfileChunk = 0x2007;
constexpr std::uint16_t kTagsChunk = 0x2018;
constexpr std::uint16_t kPaletteChunk = 0x2019;
constexpr std::uint16_t kUserDataChunk = 0x2020;
constexpr std::uint16_t kSliceChunk = 0x2022;
constexpr std::size_t kPaletteColours = 32;

// A frame being written: its chunks counted, its size written back at the end.
class FrameWriter {
 public:
  FrameWriter(ByteWriter& out, int duration_ms) : out_(out), start_(out.size()) {
    out_.u32(0);  // bytes in the frame, written back by finish()
    out_.u16(kFrameMagic);
    out_.u16(0);  // chunks (the old 16-bit field), written back
    out_.u16(static_cast<std::uint16_t>(std::clamp(duration_ms, 1, 0xFFFF)));
    out_.zeros(2);
    out_.u32(0);  // chunks, written back
  }

  std::size_t begin_chunk(std::uint16_t type) {
    ++chunks_;
    const std::size_t at = out_.size();
    out_.u32(0);
    out_.u16(type);
    return at;
  }
  void end_chunk(std::size_t at) { out_.patch_u32(at, static_cast<std::uint32_t>(out_.size() - at)); }

  void finish() {
    out_.patch_u32(start_, static_cast<std::uint32_t>(out_.size() - start_));
    const std::uint32_t old_count = std::min<std::uint32_t>(chunks_, 0xFFFF);
    out_.patch_u16(start_ + 6, static_cast<std::uint16_t>(old_count));
    out_.patch_u32(start_ + 12, chunks_);
  }

 private:
  ByteWriter& out_;
  std::size_t start_;
  std::uint32_t chunks_ = 0;
};

void write_header(ByteWriter& out, int frames, int width, int height, int speed_ms, int colours) {
  out.u32(0);  // file size, written back
  out.u16(kFileMagic);
  out.u16(static_cast<std::uint16_t>(frames));
  out.u16(static_cast<std::uint16_t>(width));
  out.u16(static_cast<std::uint16_t>(height));
  out.u16(32);  // RGBA
  out.u32(1);   // layer opacity is valid
  out.u16(static_cast<std::uint16_t>(std::clamp(speed_ms, 1, 0xFFFF)));
  out.zeros(8);
  out.u8(0);  // transparent index: indexed sprites only
  out.zeros(3);
  out.u16(static_cast<std::uint16_t>(colours));
  out.u8(1);  // square pixels
  out.u8(1);
  out.zeros(8);  // no grid
  out.zeros(84);
}

void write_colour_profile(FrameWriter& frame, ByteWriter& out) {
  const std::size_t at = frame.begin_chunk(kColorProfileChunk);
  out.u16(1);  // sRGB, as the renders are encoded
  out.u16(0);
  out.u32(0);
  out.zeros(8);
  frame.end_chunk(at);
}

using Rgba = std::array<std::uint8_t, 4>;

// The opaque colours most pixels have (toon bands, lines): the swatches an
// artist retouching the frames reaches for. Black alone when none is opaque.
std::vector<Rgba> most_used_colours(const std::vector<AsepriteLayer>& layers, const AtlasView& view) {
  std::map<Rgba, long long> counts;
  for (const AsepriteLayer& layer : layers) {
    for (const AtlasFrame& frame : view.frames) {
      for (int y = frame.frame.y; y < frame.frame.y + frame.frame.h; ++y) {
        const std::uint8_t* p = layer.sheet->pixel(frame.frame.x, y);
        for (int x = 0; x < frame.frame.w; ++x, p += 4) {
          if (p[3] == 255) ++counts[{p[0], p[1], p[2], p[3]}];
        }
      }
    }
  }
  std::vector<std::pair<long long, Rgba>> ranked;
  for (const auto& [colour, count] : counts) ranked.push_back({-count, colour});
  std::sort(ranked.begin(), ranked.end());
  std::vector<Rgba> colours;
  for (std::size_t i = 0; i < ranked.size() && i < kPaletteColours; ++i) colours.push_back(ranked[i].second);
  if (colours.empty()) colours.push_back({0, 0, 0, 255});
  return colours;
}

void write_palette(FrameWriter& frame, ByteWriter& out, const std::vector<Rgba>& colours) {
  const std::size_t at = frame.begin_chunk(kPaletteChunk);
  out.u32(static_cast<std::uint32_t>(colours.size()));
  out.u32(0);
  out.u32(static_cast<std::uint32_t>(colours.size() - 1));
  out.zeros(8);
  for (const Rgba& c : colours) {
    out.u16(0);  // no name
    for (std::uint8_t v : c) out.u8(v);
  }
  frame.end_chunk(at);
}

std::uint8_t loop_direction(const std::string& direction) {
  if (direction == "reverse") return 1;
  if (direction == "pingpong") return 2;
  if (direction == "pingpong_reverse") return 3;
  return 0;
}

// Tags told apart at a glance in Aseprite's timeline.
Rgba tag_colour(std::size_t index) {
  static constexpr std::array<Rgba, 6> kColours{{{0xD9, 0x5B, 0x43, 255},
                                                 {0x4C, 0x9F, 0x70, 255},
                                                 {0x3D, 0x7E, 0xC4, 255},
                                                 {0xE0, 0xA4, 0x2E, 255},
                                                 {0x8E, 0x5B, 0xC8, 255},
                                                 {0x3A, 0xB0, 0xB8, 255}}};
  return kColours[index % kColours.size()];
}

// The tags, then one user data chunk per tag with its colour, in order.
void write_tags(FrameWriter& frame, ByteWriter& out, const std::vector<AtlasTag>& tags) {
  if (tags.empty()) return;
  const std::size_t at = frame.begin_chunk(kTagsChunk);
  out.u16(static_cast<std::uint16_t>(std::min<std::size_t>(tags.size(), 0xFFFF)));
  out.zeros(8);
  for (std::size_t i = 0; i < tags.size() && i < 0xFFFF; ++i) {
    const AtlasTag& tag = tags[i];
    out.u16(static_cast<std::uint16_t>(tag.from));
    out.u16(static_cast<std::uint16_t>(tag.to));
    out.u8(loop_direction(tag.direction));
    out.u16(static_cast<std::uint16_t>(std::clamp(tag.repeat, 0, 0xFFFF)));
    out.zeros(6);
    const Rgba colour = tag_colour(i);
    for (int c = 0; c < 3; ++c) out.u8(colour[c]);
    out.u8(0);
    out.string(tag.name);
  }
  frame.end_chunk(at);
  for (std::size_t i = 0; i < tags.size() && i < 0xFFFF; ++i) {
    const std::size_t data = frame.begin_chunk(kUserDataChunk);
    out.u32(2);  // has a colour
    for (std::uint8_t v : tag_colour(i)) out.u8(v);
    frame.end_chunk(data);
  }
}

void write_layers(FrameWriter& frame, ByteWriter& out, const std::vector<AsepriteLayer>& layers) {
  for (const AsepriteLayer& layer : layers) {
    const std::size_t at = frame.begin_chunk(kLayerChunk);
    out.u16(1 | 2);  // visible, editable
    out.u16(0);      // an image layer
    out.u16(0);      // at the top level
    out.u16(0);
    out.u16(0);
    out.u16(0);  // normal blending
    out.u8(255);
    out.zeros(3);
    out.string(layer.name);
    frame.end_chunk(at);
  }
}

// Where a frame's anchor falls on the canvas, in whole pixels.
std::array<int, 2> pivot_of(const AtlasFrame& frame) {
  return {static_cast<int>(std::lround(frame.anchor_x * frame.tile_w)),
          static_cast<int>(std::lround(frame.anchor_y * frame.tile_h))};
}

void write_pivot_slice(FrameWriter& frame, ByteWriter& out, const AtlasView& view) {
  std::vector<std::size_t> keys;
  for (std::size_t i = 0; i < view.frames.size(); ++i) {
    if (i == 0 || pivot_of(view.frames[i]) != pivot_of(view.frames[keys.back()])) keys.push_back(i);
  }
  const std::size_t at = frame.begin_chunk(kSliceChunk);
  out.u32(static_cast<std::uint32_t>(keys.size()));
  out.u32(2);  // has a pivot
  out.u32(0);
  out.string("pivot");
  for (std::size_t i : keys) {
    const AtlasFrame& f = view.frames[i];
    out.u32(static_cast<std::uint32_t>(i));
    out.i32(0);
    out.i32(0);
    out.u32(static_cast<std::uint32_t>(f.tile_w));
    out.u32(static_cast<std::uint32_t>(f.tile_h));
    const std::array<int, 2> pivot = pivot_of(f);
    out.i32(pivot[0]);
    out.i32(pivot[1]);
  }
  frame.end_chunk(at);
}

std::string zlib_compressed(const image::Image& sheet, const PixelRect& rect) {
  std::string raw;
  raw.reserve(static_cast<std::size_t>(rect.w) * rect.h * 4);
  for (int y = rect.y; y < rect.y + rect.h; ++y) {
    raw.append(reinterpret_cast<const char*>(sheet.pixel(rect.x, y)), static_cast<std::size_t>(rect.w) * 4);
  }
  uLongf size = compressBound(static_cast<uLong>(raw.size()));
  std::string packed(size, '\0');
  if (compress2(reinterpret_cast<Bytef*>(packed.data()), &size, reinterpret_cast<const Bytef*>(raw.data()),
                static_cast<uLong>(raw.size()), Z_DEFAULT_COMPRESSION) != Z_OK) {
    throw std::runtime_error("aseprite: zlib could not compress a cel");
  }
  packed.resize(size);
  return packed;
}

// The layer's pixels of one frame, cut to the visible ones, at their place
// in the tile; nothing when the frame of this layer is empty.
void write_cel(FrameWriter& frame, ByteWriter& out, int layer_index, const image::Image& sheet,
               const AtlasFrame& atlas_frame) {
  const PixelRect cel = visible_bounds(sheet, atlas_frame.frame);
  if (cel.w == 0) return;
  const std::size_t at = frame.begin_chunk(kCelChunk);
  out.u16(static_cast<std::uint16_t>(layer_index));
  out.i16(static_cast<std::int16_t>(atlas_frame.source.x + cel.x - atlas_frame.frame.x));
  out.i16(static_cast<std::int16_t>(atlas_frame.source.y + cel.y - atlas_frame.frame.y));
  out.u8(255);
  out.u16(2);  // a compressed image
  out.i16(0);  // z-index: the layer's own order
  out.zeros(5);
  out.u16(static_cast<std::uint16_t>(cel.w));
  out.u16(static_cast<std::uint16_t>(cel.h));
  out.bytes(zlib_compressed(sheet, cel));
  frame.end_chunk(at);
}

void check_limits(const AtlasView& view) {
  if (view.frames.empty()) throw std::invalid_argument("aseprite: a sheet with no frames");
  if (view.frames.size() > static_cast<std::size_t>(kAsepriteMaxFrames)) {
    throw std::invalid_argument("aseprite: more than 65535 frames");
  }
  const AtlasFrame& first = view.frames.front();
  if (first.tile_w > kAsepriteMaxSide || first.tile_h > kAsepriteMaxSide) {
    throw std::invalid_argument("aseprite: a tile wider or taller than 32767 pixels");
  }
}

}  // namespace

std::string aseprite_file(const std::vector<AsepriteLayer>& layers, const nlohmann::ordered_json& atlas) {
  const AtlasView view = view_of(atlas);
  check_limits(view);
  const std::vector<Rgba> colours = most_used_colours(layers, view);
  ByteWriter out;
  const AtlasFrame& first = view.frames.front();
  write_header(out, static_cast<int>(view.frames.size()), first.tile_w, first.tile_h, first.duration_ms,
               static_cast<int>(colours.size()));
  for (std::size_t i = 0; i < view.frames.size(); ++i) {
    FrameWriter frame(out, view.frames[i].duration_ms);
    if (i == 0) {
      write_colour_profile(frame, out);
      write_palette(frame, out, colours);
      write_tags(frame, out, view.tags);
      write_layers(frame, out, layers);
      write_pivot_slice(frame, out, view);
    }
    for (std::size_t l = 0; l < layers.size(); ++l) {
      write_cel(frame, out, static_cast<int>(l), *layers[l].sheet, view.frames[i]);
    }
    frame.finish();
  }
  out.patch_u32(0, static_cast<std::uint32_t>(out.size()));
  return out.take();
}

}  // namespace toond::sheet_files
