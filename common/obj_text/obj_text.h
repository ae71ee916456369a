#pragma once
// Rewrites of OBJ text that tinyobjloader would otherwise misread. They keep
// the meaning and the line numbering of the file (so parser messages still
// point at the right line).
#include <string>
#include <string_view>

namespace toond::obj_text {

// - A line ending in '\' continues on the next line (Rhino writes long faces
//   so); the pieces are joined and blank lines keep the numbering.
// - Empty index slots in f/l/p corners ("1//", "2/2/") are dropped; tinyobj
//   would read them as index 0 and reject the file.
// - An `mtllib` line with blanks or '\' in it has them escaped, so that
//   tinyobj hands it to the material reader as one name instead of cutting
//   it (see mtllib_line_in_one_piece).
// - `usemtl` names containing blanks become material_alias(name), since
//   tinyobj keeps only the first word of a usemtl name but the whole line of
//   a newmtl name.
// - A face of more than 256 corners becomes a triangle fan, one `f` line per
//   triangle (tinyobj's ear clipping would take time growing with the
//   square of the corners or worse); only such faces shift later lines.
//
// `findings`, when given, says what the text holds that tinyobj would pass
// over without a word: the first face naming a vertex position the file
// does not define (tinyobj drops such quads silently).
struct ObjTextFindings {
  std::size_t missing_vertex_line = 0;  // 1-based; 0: none
};
std::string prepare_obj_text(std::string_view text, ObjTextFindings* findings = nullptr);

// A single-token stand-in for a material name: trimmed, each run of blanks
// replaced by one U+001F. Names without blanks are returned trimmed.
std::string material_alias(std::string_view name);

}  // namespace toond::obj_text
