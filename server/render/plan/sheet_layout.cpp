#include "render/plan/sheet_layout.h"

#include <algorithm>
#include <cmath>

namespace toond::render {
namespace {

// The same angle in [0, 360): the atlas and the frame's render both use it,
// so a single render asked for the atlas's yaw sees exactly the same view.
double normalised_yaw(double deg) {
  const double wrapped = std::fmod(deg, 360.0);
  return wrapped < 0.0 ? wrapped + 360.0 : wrapped;
}

// Frame k's share of a clip `length_ms` long in `count` frames: the
// rounded ends of its exact span, so the shares add up to the rounded
// length and none is off by more than a millisecond.
int whole_ms(double length_ms, int k, int count) {
  const auto end = [&](int i) { return std::llround(length_ms * i / count); };
  return std::max(1, static_cast<int>(end(k + 1) - end(k)));
}

// The time between a clip's neighbouring frames, which each frame shows
// for: a loop's frames share out its length (the end is the start again);
// a one-shot's reach its end, one step fewer, and its last pose shows for
// a step too (a one-shot of one frame: its start, for its length).
double clip_step(const SheetClip& clip) {
  if (clip.loop || clip.frame_count < 2) return clip.duration / clip.frame_count;
  return clip.duration / (clip.frame_count - 1);
}

SheetLayout layout_clips(const SheetParams& sheet, int tile_width, int tile_height) {
  SheetLayout layout;
  layout.tile_width = tile_width;
  layout.tile_height = tile_height;
  layout.padding = sheet.padding;
  for (const SheetClip& clip : sheet.clips) layout.columns = std::max(layout.columns, clip.frame_count);
  int row = 0;
  int index = 0;
  for (std::size_t c = 0; c < sheet.clips.size(); ++c) {
    const SheetClip& clip = sheet.clips[c];
    const double step = clip_step(clip);
    const double row_ms = (clip.loop ? clip.duration : step * clip.frame_count) * 1000.0;
    for (const double pitch : sheet.pitches_deg) {
      for (int d = 0; d < sheet.frames; ++d, ++row) {
        for (int k = 0; k < clip.frame_count; ++k) {
          SheetFrame frame;
          frame.index = index++;
          frame.x = k * (tile_width + sheet.padding);
          frame.y = row * (tile_height + sheet.padding);
          frame.yaw_deg = normalised_yaw(sheet.yaw_start_deg + d * sheet.yaw_step_deg);
          frame.pitch_deg = pitch;
          frame.clip = static_cast<int>(c);
          frame.time = clip.span.start + k * step;
          frame.duration_ms = step > 0.0 ? whole_ms(row_ms, k, clip.frame_count) : sheet.frame_ms;
          layout.frames.push_back(frame);
        }
      }
    }
  }
  layout.rows = row;
  layout.width = layout.columns * tile_width + (layout.columns - 1) * sheet.padding;
  layout.height = layout.rows * tile_height + (layout.rows - 1) * sheet.padding;
  return layout;
}

}  // namespace

SheetLayout layout_sheet(const SheetParams& sheet, int tile_width, int tile_height) {
  if (!sheet.clips.empty()) return layout_clips(sheet, tile_width, tile_height);
  SheetLayout layout;
  layout.tile_width = tile_width;
  layout.tile_height = tile_height;
  layout.columns = std::min(sheet.columns, sheet.frames);
  layout.padding = sheet.padding;
  const int rows_per_pitch = (sheet.frames + layout.columns - 1) / layout.columns;
  layout.rows = rows_per_pitch * static_cast<int>(sheet.pitches_deg.size());
  layout.width = layout.columns * tile_width + (layout.columns - 1) * sheet.padding;
  layout.height = layout.rows * tile_height + (layout.rows - 1) * sheet.padding;
  int index = 0;
  for (std::size_t p = 0; p < sheet.pitches_deg.size(); ++p) {
    for (int f = 0; f < sheet.frames; ++f) {
      const int row = static_cast<int>(p) * rows_per_pitch + f / layout.columns;
      const int column = f % layout.columns;
      SheetFrame frame;
      frame.index = index++;
      frame.x = column * (tile_width + sheet.padding);
      frame.y = row * (tile_height + sheet.padding);
      frame.yaw_deg = normalised_yaw(sheet.yaw_start_deg + f * sheet.yaw_step_deg);
      frame.pitch_deg = sheet.pitches_deg[p];
      frame.duration_ms = sheet.frame_ms;
      layout.frames.push_back(frame);
    }
  }
  return layout;
}

RenderParams frame_params(const RenderParams& sheet_params, const SheetLayout& layout, const SheetFrame& frame) {
  RenderParams params = sheet_params;
  params.sheet.reset();
  params.camera.yaw_deg = frame.yaw_deg;
  params.camera.pitch_deg = frame.pitch_deg;
  params.camera.framed_views.clear();
  for (const SheetFrame& other : layout.frames) params.camera.framed_views.emplace_back(other.yaw_deg, other.pitch_deg);
  return params;
}

}  // namespace toond::render
