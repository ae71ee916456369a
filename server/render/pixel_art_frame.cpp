#include "render/pixel_art_frame.h"

namespace toond::render {

RenderParams pixel_art_frame_params(RenderParams frame, int scale) {
  frame.width /= scale;
  frame.height /= scale;
  // Antialiasing would make in-between colours along every edge: after
  // quantising each becomes whichever palette entry is nearest, often a
  // third colour, which reads as noise on a silhouette and crawls as the
  // model turns. Pixel art wants every pixel inside or outside.
  frame.msaa = 1;
  frame.supersample = 1;
  // Band antialiasing blends the two bands across one pixel at each band
  // edge, the same in-between colours along every terminator; off, each
  // pixel is exactly one band's colour, which the palette keeps or snaps.
  frame.band_aa = false;
  return frame;
}

}  // namespace toond::render
