#include "pipeline/frames.h"

#include "render/plan/pixel_art_frame.h"

namespace toond::pipeline {

std::optional<render::SheetLayout> layout_of(const render::RenderParams& params) {
  if (!params.sheet) return std::nullopt;
  return render::layout_sheet(*params.sheet, params.width, params.height);
}

std::vector<render::RenderParams> drawn_frames(const render::RenderParams& params,
                                               const std::optional<render::SheetLayout>& layout) {
  if (!layout) return {params};
  std::vector<render::RenderParams> frames;
  for (const render::SheetFrame& frame : layout->frames) {
    render::RenderParams one = render::frame_params(params, *layout, frame);
    if (params.sheet->pixel_art) one = render::pixel_art_frame_params(std::move(one), *params.sheet->pixel_art);
    frames.push_back(std::move(one));
  }
  return frames;
}

}  // namespace toond::pipeline
