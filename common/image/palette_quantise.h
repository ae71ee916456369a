#pragma once
// Reducing images to a small palette of sRGB colours, for pixel art: one
// palette chosen over many images at once (a sprite sheet's frames), so a
// colour maps to the same entry in every frame, then each image mapped onto
// it. Only pixels with alpha above 0 count and change: fully transparent
// pixels are background, not picture. Alpha itself is left as it is.
#include <cstdint>
#include <span>
#include <vector>

#include "image/image.h"

namespace toond::image {

struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb8&, const Rgb8&) = default;
};

// At most `colours` entries (1 or more) chosen by median cut over the
// visible pixels of all `images`: the box of colours holding the most
// pixels × widest channel range is split at its pixel-weighted median along
// that channel until there are `colours` boxes or none can be split; each
// box gives its pixel-weighted mean. When the images hold no more distinct
// colours than `colours`, the palette is exactly those colours. The result
// depends only on the pixels, not on the order of the images or of the
// pixels within them, and is sorted (by r, g, b). Empty when no pixel is
// visible.
std::vector<Rgb8> median_cut_palette(std::span<const Image* const> images, int colours);

// The index of the palette entry nearest `c` (squared distance in sRGB
// bytes; ties go to the lower index). `palette` must not be empty.
int nearest_entry(std::span<const Rgb8> palette, Rgb8 c);

// Replaces the colour of every visible pixel of `image` by a palette entry:
// without `dither` the nearest one; with it, the nearest to the colour
// shifted by a 4×4 Bayer threshold (ordered dithering), whose amplitude is
// the mean spacing of the palette's colours, so a pattern mixes neighbouring
// entries and a pixel's choice depends only on its colour and position.
// `palette` must not be empty.
void quantise_to_palette(Image& image, std::span<const Rgb8> palette, bool dither);

}  // namespace toond::image
