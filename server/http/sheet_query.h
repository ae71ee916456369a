#pragma once
// The query of a render request that picks what a sheet answers:
// ?atlas=json (the atlas alone), ?atlas=aseprite (one .aseprite file),
// ?atlas=godot (a Godot 4 SpriteFrames resource) and, with godot,
// ?texture= (the sheet's PNG as the resource names it). Nothing else rides
// in the query.
#include <string>

#include <httplib.h>

#include "pipeline/sheet_file.h"

namespace toond::http {

// Throws RequestError 400 at ?atlas for another value, at ?texture for a
// texture without ?atlas=godot or a path Godot would not take (empty,
// absolute outside res:// and user://, another scheme, control
// characters, longer than 1024 bytes).
pipeline::SheetAnswer sheet_answer_of(const httplib::Request& req);

}  // namespace toond::http
