#pragma once
// The atlas of a sprite sheet: TexturePacker's "hash" JSON layout, which
// game engines import as it is (`frames` → `frame`, `spriteSourceSize`,
// `sourceSize`, `pivot`; `meta` with `size` and `image`), with toond's own
// keys beside them: each frame's yaw and pitch, and in `meta` the framing
// every frame shares, so that a single render can ask for the same view.
#include <string>

#include <nlohmann/json.hpp>

#include "render/camera.h"
#include "render/render_params.h"
#include "render/sheet_layout.h"

namespace toond::render {

// `params` are the sheet's render parameters, `scene` the framing's view of
// the models (frame_scene of the job's objects). Frames are named
// "frame_000", "frame_001", … in layout order. A frame's pivot is where the
// point under the orbit's centre, at the foot of the bounds, lands in its
// tile (0..1 from the top left): the spot a game stands the sprite on.
nlohmann::json sheet_atlas(const SheetLayout& layout, const RenderParams& params, const SceneFrame& scene,
                           const std::string& image_name);

}  // namespace toond::render
