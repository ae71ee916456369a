#pragma once
// Where each frame of a sprite sheet goes and which view it shows. Pure
// arithmetic on the resolved `sheet` parameters: the pipeline checks
// limits and writes the atlas from it before anything is rendered.
#include <vector>

#include "render/plan/render_params.h"

namespace toond::render {

struct SheetFrame {
  int index = 0;  // 0 .. frames × pitches − 1, row by row
  int x = 0;      // the tile's top-left pixel in the sheet
  int y = 0;
  double yaw_deg = 0;  // in [0, 360)
  double pitch_deg = 0;
  // An animated sheet's frame: which of SheetParams::clips, at which time
  // (seconds on the file's time base, inside the clip's span).
  int clip = -1;  // -1: a turntable frame
  double time = 0;
  // How long the frame shows, in whole milliseconds (what game engines
  // play): a clip's frames round their exact times so that a looping row
  // adds up to the clip's length (83, 84, 83 ms for a quarter second in
  // three), a one-shot's to its length and one step more (its last pose
  // shows for a step too), at least 1 ms each; a turntable's frames, and a
  // clip of no length, show for `frame_ms`.
  int duration_ms = 0;
};

struct SheetLayout {
  int tile_width = 0;
  int tile_height = 0;
  int columns = 0;
  int rows = 0;     // per pitch, ceil(frames / columns); then times the pitches
  int padding = 0;  // between neighbouring tiles, not around the edge
  int width = 0;    // of the whole sheet
  int height = 0;
  std::vector<SheetFrame> frames;
};

// Pitch by pitch, frames fill rows of `columns` tiles from the top left; a
// pitch's last row may be short, and the next pitch starts a new row. An
// animated sheet (resolved clips) has instead, clip by clip and pitch by
// pitch, a row per direction of the clip's frames over its span: a loop's
// at start + k · length / frames, a one-shot's at start + k · length /
// (frames − 1), its last pose included.
SheetLayout layout_sheet(const SheetParams& sheet, int tile_width, int tile_height);

// The parameters of one frame's render: the sheet's own, turned to the
// frame's view, framed to hold every frame of the sheet, and with no sheet.
RenderParams frame_params(const RenderParams& sheet_params, const SheetLayout& layout, const SheetFrame& frame);

}  // namespace toond::render
