#pragma once
// Measurements on rendered images for tests: what covers the background,
// how many distinct flat colours a region holds, whether an outline ring
// closes around a silhouette.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "image/image.h"

namespace toond::test {

using image::Image;

struct Rgb {
  std::uint8_t r, g, b;
  auto operator<=>(const Rgb&) const = default;
};

Rgb rgb_at(const Image& img, int x, int y);
double luminance(Rgb c);  // 0..1, from sRGB bytes (approximate, for thresholds)

// Pixels whose colour differs from the corner pixel's (the background).
std::vector<bool> foreground_mask(const Image& img);
double coverage(const std::vector<bool>& mask);
std::size_t count(const std::vector<bool>& mask);

// Share of the pixels of two same-sized images whose colour differs by more
// than `levels` in some channel (alpha not compared).
double differing_share(const Image& a, const Image& b, int levels);

// Colours inside `mask` and how many pixels have each.
std::map<Rgb, std::size_t> colour_histogram(const Image& img, const std::vector<bool>& mask);
// Colours holding at least `min_fraction` of the masked pixels.
std::size_t dominant_colours(const Image& img, const std::vector<bool>& mask, double min_fraction);

// Pixels of `mask` that touch a pixel outside it (4-neighbourhood).
std::vector<bool> boundary(const std::vector<bool>& mask, int width, int height);

// The width of an outline, from a render without it (`bare`) and one with
// it: the median distance from the ring's outer edge to the nearest model
// pixel, in pixels. Corners (where mitres reach further) barely move a median.
double outline_width_px(const Image& bare, const Image& outlined);
// The same distances' largest: how far the outline reaches anywhere (a
// spike shows here, not in the median).
double outline_reach_px(const Image& bare, const Image& outlined);

}  // namespace toond::test
