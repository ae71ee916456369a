#include "render/frame/ramp_image.h"

#include <cstring>
#include <string>

namespace toond::render {

std::vector<RampStop> ramp_from_image(const scene::Texture& image) {
  if (image.width <= 0 || image.height <= 0) throw RampImageError("the ramp image is empty");
  const std::size_t row = static_cast<std::size_t>(image.height / 2) * static_cast<std::size_t>(image.width) * 4;
  const std::uint8_t* texels = image.rgba.data() + row;
  std::vector<RampStop> stops;
  for (int i = 0; i < image.width; ++i) {
    const std::uint8_t* t = texels + static_cast<std::size_t>(i) * 4;
    if (i > 0 && std::memcmp(t, t - 4, 3) == 0) continue;
    if (static_cast<int>(stops.size()) == max_ramp_bands) {
      int runs = static_cast<int>(stops.size());
      for (int j = i; j < image.width; ++j) {
        if (std::memcmp(texels + static_cast<std::size_t>(j) * 4, texels + static_cast<std::size_t>(j - 1) * 4, 3) != 0)
          ++runs;
      }
      throw RampImageError("the ramp image has " + std::to_string(runs) + " runs of equal texels; at most " +
                           std::to_string(max_ramp_bands) + " bands fit a ramp");
    }
    RampStop stop;
    stop.at = i == 0 ? -1.0f : static_cast<float>(i) / static_cast<float>(image.width);
    stop.color = srgb_to_linear(glm::vec3(t[0], t[1], t[2]) / 255.0f);
    stops.push_back(stop);
  }
  return stops;
}

}  // namespace toond::render
