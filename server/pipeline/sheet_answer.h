#pragma once
// What a sheet answers (?atlas=…) and the stage that writes it from the
// assembled sheet: its image (PNG, or WebP with animate), its atlas alone
// (JSON), one .aseprite file, or a Godot 4 SpriteFrames resource; and
// `sheet.pack`, which trims and packs the sheet's image and its atlas
// before any of them is written (server/sheet_files/). The atlas written by
// render/atlas is the one source: every file says what it says.
#include <string>

#include <nlohmann/json.hpp>

#include "pipeline/sheet_file.h"
#include "render/frame/render_output.h"

namespace toond::pipeline {

struct Request;
struct Encoded;

// Throws RequestError 400 when the answer cannot be had from the request:
// a file of a request without `sheet` (at /sheet), an .aseprite file of a
// data layer (at /output), an .aseprite file or Godot resource of an
// animated WebP (at /sheet/animate); 422 at /sheet for an .aseprite file of
// more frames than the format counts.
void check_sheet_answer(const Request& request);

// Whether the answer needs the sheet drawn: its image, an .aseprite file's
// pixels, or a packed sheet's atlas (the trims are the pixels').
bool needs_drawing(const Request& request);

// sheet.pack: `out.image` (and the sheet's other layers, out.other_layers:
// each tile cut to all the layers' pixels) trimmed and packed, and `atlas`
// rewritten to match (sheet_files/packed_sheet.h), with the sheet's padding
// between tiles and its power_of_two; its time goes into out.timings as
// `pack`.
void pack_sheet_output(render::RenderOutput& out, nlohmann::ordered_json& atlas, const Request& request);

// The answer's bytes when it is a file and not the image: the atlas as JSON
// or a Godot resource (`out` may then be null: nothing was drawn), or the
// .aseprite file of `out`'s sheet, a layer per layer drawn (sheet_layers.h:
// the output alone, or sheet.layers), named `color` and `lines`, lines
// above.
Encoded encode_sheet_file(const render::RenderOutput* out, const Request& request, const nlohmann::ordered_json& atlas);

}  // namespace toond::pipeline
