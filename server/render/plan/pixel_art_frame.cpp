#include "render/plan/pixel_art_frame.h"

namespace toond::render {
namespace {

// What a sprite artist draws at a few dozen pixels: a silhouette one pixel
// wide, and inner lines only where both sides stay readable. The defaults
// counted in art pixels (a 2-pixel outline, crease lines on every block of
// a blocky character) fill a small head with line colour.
void draw_lines_as_a_sprite(RenderParams& frame) {
  frame.outline.width = 1;
  frame.outline.units = OutlineUnits::Pixels;
  frame.outline.readable_area_px = kReadableAreaArtPx;
  frame.outline.whole_pixel_lines = true;
  // Both rules are about pixels: the edge pass, which sees them, finds the
  // crease lines (on a frame of a few dozen pixels it costs little).
  frame.outline.screen_space_creases = true;
  // Contour lines run inside the silhouette wherever the surface turns
  // away; at this size they would double the outline on every limb.
  frame.contour.enabled = false;
}

}  // namespace

RenderParams pixel_art_frame_params(RenderParams frame, const SheetParams::PixelArt& art) {
  frame.width /= art.scale;
  frame.height /= art.scale;
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
  if (art.lines == SheetParams::PixelArt::Lines::Sprite) draw_lines_as_a_sprite(frame);
  return frame;
}

}  // namespace toond::render
