#include "render/passes/passes.h"

namespace toond::render {

DrawPass drawing_pass(Pass pass) {
  switch (pass) {
    case Pass::Shadow:
      return draw_shadow_pass;
    case Pass::Main:
      return draw_main_pass;
    case Pass::Floor:
      return draw_floor_pass;
    case Pass::HullOutline:
      return draw_hull_outline_pass;
    case Pass::Wireframe:
      return draw_wireframe_pass;
    case Pass::Creases:
      return draw_crease_pass;
    case Pass::EdgePrepass:
      return draw_edge_prepass;
    case Pass::Edges:
      return draw_edge_pass;
    case Pass::Layer:
      return draw_layer_pass;
    case Pass::Downsample:
      return draw_downsample_pass;
    case Pass::Resolve:
    case Pass::Readback:
    case Pass::Unpremultiply:
      return nullptr;
  }
  return nullptr;
}

}  // namespace toond::render
