#pragma once
#include "scene/reading/bundle.h"

namespace toond::scene {

// The built-in demo: an OBJ + MTL + PNG bundle generated here (no file from
// outside the project), so a fresh install renders something without an
// upload. It has a smooth part (a UV sphere) standing on a hard-edged part (a
// bevel-free box) and a procedural texture, which exercises bands, texture
// sampling and the outline at hard edges. It also carries a ramp image
// (ramps/sharp.png) and a floor texture (textures/floor.png) that requests
// may name. Deterministic: same bytes every call.
Bundle make_demo_bundle();

}  // namespace toond::scene
