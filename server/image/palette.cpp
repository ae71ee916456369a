#include "image/palette.h"

#include <cstring>

namespace toond::image {
namespace {

std::uint32_t load_pixel(const std::uint8_t* p) {
  std::uint32_t v;
  std::memcpy(&v, p, 4);
  return v;
}

Rgba8 unpack(std::uint32_t packed) {
  std::uint8_t bytes[4];
  std::memcpy(bytes, &packed, 4);
  return {bytes[0], bytes[1], bytes[2], bytes[3]};
}

// Open addressing over four times more slots than colours allowed, so a
// probe rarely goes past its first slot; small enough to stay in L1.
class ColourTable {
 public:
  // The colour's index, a new one if unseen; -1 once the palette is full.
  int index_of(std::uint32_t colour) {
    for (std::uint32_t slot = hash(colour);; slot = (slot + 1) & kMask) {
      if (index_[slot] < 0) {
        if (colours_.size() == kMaxPaletteColours) return -1;
        keys_[slot] = colour;
        index_[slot] = static_cast<std::int16_t>(colours_.size());
        colours_.push_back(colour);
        return index_[slot];
      }
      if (keys_[slot] == colour) return index_[slot];
    }
  }
  const std::vector<std::uint32_t>& colours() const { return colours_; }

 private:
  static constexpr std::uint32_t kBits = 10;
  static constexpr std::uint32_t kMask = (1u << kBits) - 1;
  static std::uint32_t hash(std::uint32_t colour) { return (colour * 0x9E3779B1u) >> (32 - kBits); }

  std::array<std::uint32_t, 1u << kBits> keys_{};
  std::array<std::int16_t, 1u << kBits> index_ = [] {
    std::array<std::int16_t, 1u << kBits> empty{};
    empty.fill(-1);
    return empty;
  }();
  std::vector<std::uint32_t> colours_;
};

// Writes the index of every pixel behind each row's filter byte. Toon frames
// are long runs of one colour, so a pixel equal to its left neighbour reuses
// that index without touching the table.
bool index_pixels(const Image& image, ColourTable& table, std::vector<std::uint8_t>& scanlines) {
  const std::size_t stride = static_cast<std::size_t>(image.width) + 1;
  std::uint32_t previous = load_pixel(image.pixel(0, 0));
  int previous_index = table.index_of(previous);
  for (int y = 0; y < image.height; ++y) {
    const std::uint8_t* in = image.pixel(0, y);
    std::uint8_t* out = scanlines.data() + static_cast<std::size_t>(y) * stride;
    *out++ = 0;
    for (int x = 0; x < image.width; ++x, in += 4) {
      const std::uint32_t colour = load_pixel(in);
      if (colour != previous) {
        previous = colour;
        previous_index = table.index_of(colour);
        if (previous_index < 0) return false;
      }
      out[x] = static_cast<std::uint8_t>(previous_index);
    }
  }
  return true;
}

// Moves translucent colours to the front (keeping first-seen order within
// each group) and renumbers the indices to match.
void put_translucent_first(PalettedImage& result, const Image& image) {
  std::array<std::uint8_t, kMaxPaletteColours> new_index{};
  std::vector<Rgba8> ordered;
  ordered.reserve(result.colours.size());
  for (const bool translucent : {true, false}) {
    for (std::size_t i = 0; i < result.colours.size(); ++i) {
      if ((result.colours[i].a < 255) != translucent) continue;
      new_index[i] = static_cast<std::uint8_t>(ordered.size());
      ordered.push_back(result.colours[i]);
    }
  }
  result.colours = std::move(ordered);
  const std::size_t stride = static_cast<std::size_t>(image.width) + 1;
  for (int y = 0; y < image.height; ++y) {
    std::uint8_t* row = result.scanlines.data() + static_cast<std::size_t>(y) * stride + 1;
    for (int x = 0; x < image.width; ++x) row[x] = new_index[row[x]];
  }
}

}  // namespace

std::optional<PalettedImage> make_palette(const Image& image) {
  if (image.width <= 0 || image.height <= 0) return std::nullopt;
  PalettedImage result;
  result.scanlines.resize((static_cast<std::size_t>(image.width) + 1) * image.height);
  ColourTable table;
  if (!index_pixels(image, table, result.scanlines)) return std::nullopt;

  result.colours.reserve(table.colours().size());
  bool translucent_after_opaque = false;
  for (const std::uint32_t packed : table.colours()) {
    const Rgba8 colour = unpack(packed);
    if (colour.a < 255) {
      translucent_after_opaque |= result.translucent_count < static_cast<int>(result.colours.size());
      ++result.translucent_count;
    }
    result.colours.push_back(colour);
  }
  if (translucent_after_opaque) put_translucent_first(result, image);
  return result;
}

}  // namespace toond::image
