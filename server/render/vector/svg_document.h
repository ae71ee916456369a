#pragma once
// A line drawing written as SVG: a `<g>` a kind of line, each an Inkscape
// layer with a stable id (silhouette, creases, intersections, boundary,
// and hidden when asked, dashed, under the others), one `<path>` a stroke
// of straight segments through points rounded to 2 decimals, the stroke
// as wide as the request's outline in pixels with round caps and joins,
// in a viewBox of the image's size (a stroke whose colour is not its
// layer's says its own); and `<metadata id="toond-camera">`
// holding the camera as JSON, so that the drawing can be laid over other
// renders or data of the same model.
#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "render/vector/line_kind.h"
#include "render/vector/stroke_chains.h"

namespace toond::render::vector {

using Srgb = std::array<std::uint8_t, 3>;

// Strokes of one colour.
struct ColouredStrokes {
  Srgb colour{0, 0, 0};
  std::vector<Polyline> strokes;
};

struct SvgDrawing {
  int width = 0, height = 0;
  double stroke_px = 1;
  Srgb colour{0, 0, 0};  // every layer's, where its strokes give none
  // Column-major, as glm and GL keep them: the model's (or scene's)
  // coordinates to view space, and view space to clip space.
  glm::dmat4 view{1.0}, projection{1.0};
  std::array<std::vector<ColouredStrokes>, kLineKinds> layers;  // by LineKind
  std::optional<std::vector<Polyline>> hidden;                  // in `colour`
};

std::string write_svg(const SvgDrawing& drawing);

// Receives the text a piece at a time; false when it wants no more (its
// client has gone).
using SvgSend = std::function<bool(std::string_view)>;

// The same text handed to `send` in pieces of about `piece_bytes` (whole
// paths), so a large drawing need never be held whole as text. False
// where `send` stopped it.
bool write_svg(const SvgDrawing& drawing, const SvgSend& send, std::size_t piece_bytes);

// About how many bytes write_svg writes for `drawing`, without writing it.
std::size_t estimated_svg_bytes(const SvgDrawing& drawing);

// The camera's JSON as the metadata holds it: {"view": [16], "projection":
// [16], "width": W, "height": H}, numbers as they round-trip.
std::string camera_json(const SvgDrawing& drawing);

// A stroke's path data: "M x,y L x,y x,y …" with 2 decimals at most, points
// that round to the one before left out, "Z" where it closes. Empty where
// nothing of it is left.
std::string path_data(const Polyline& line);

}  // namespace toond::render::vector
