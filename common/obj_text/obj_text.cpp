#include "obj_text/obj_text.h"
#include "text/trim.h"

#include <algorithm>
#include <charconv>
#include <system_error>
#include <vector>

namespace toond::obj_text {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// Statement keyword of a line and what follows it, leading blanks skipped.
bool split_statement(std::string_view line, std::string_view& keyword, std::string_view& rest) {
  std::size_t i = 0;
  while (i < line.size() && is_blank(line[i])) ++i;
  std::size_t end = i;
  while (end < line.size() && !is_blank(line[end])) ++end;
  if (end == i) return false;
  keyword = line.substr(i, end - i);
  rest = line.substr(end);
  return true;
}

std::string fix_corners(std::string_view keyword, std::string_view rest) {
  std::string out(keyword);
  std::size_t i = 0;
  while (i < rest.size()) {
    while (i < rest.size() && is_blank(rest[i])) ++i;
    std::size_t end = i;
    while (end < rest.size() && !is_blank(rest[end])) ++end;
    if (end == i) break;
    std::string_view corner = rest.substr(i, end - i);
    while (!corner.empty() && corner.back() == '/') corner.remove_suffix(1);
    out += ' ';
    out += corner;
    i = end;
  }
  return out;
}

// tinyobj triangulates a polygon by ear clipping, whose cost grows with the
// square (up to the cube) of its corner count: one uploaded face of 100 000
// corners would keep the importer busy for hours. Larger faces than any
// modelling tool writes are cut into a fan here instead.
constexpr std::size_t kMaxEarClippedCorners = 256;

std::size_t corner_count(std::string_view rest) {
  std::size_t count = 0;
  bool in_token = false;
  for (const char c : rest) {
    const bool blank = is_blank(c);
    if (!blank && !in_token) ++count;
    in_token = !blank;
  }
  return count;
}

// "f a b c d …" as the fan "f a b c", "f a c d", …: one line per triangle,
// so the lines after it shift (only for such oversized faces).
std::string fan_of(std::string_view rest) {
  std::vector<std::string_view> corners;
  std::size_t i = 0;
  while (i < rest.size()) {
    while (i < rest.size() && is_blank(rest[i])) ++i;
    std::size_t end = i;
    while (end < rest.size() && !is_blank(rest[end])) ++end;
    if (end > i) corners.push_back(rest.substr(i, end - i));
    i = end;
  }
  std::string out;
  for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
    if (!out.empty()) out += '\n';
    out += "f ";
    out += corners[0];
    out += ' ';
    out += corners[k];
    out += ' ';
    out += corners[k + 1];
  }
  return out;
}

bool needs_corner_fix(std::string_view rest) {
  for (std::size_t i = 0; i < rest.size(); ++i) {
    if (rest[i] == '/' && (i + 1 == rest.size() || is_blank(rest[i + 1]))) return true;
  }
  return false;
}

// tinyobj splits mtllib lines at blanks, reads '\' as an escape, and offers
// the pieces to the material reader one at a time until one is accepted, so
// "maps\a.mtl" lost its separator and "my model.mtl" was looked up as "my".
// With every blank and '\' escaped, the line reaches the reader whole, to be
// read by bundle_paths::mtllib_names as toon reads it.
std::string mtllib_line_in_one_piece(std::string_view rest) {
  std::string out = "mtllib ";
  for (const char c : text::trim(rest)) {
    if (c == ' ' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

}  // namespace

std::string material_alias(std::string_view name) {
  name = text::trim(name);
  std::string alias;
  bool in_blank = false;
  for (const char c : name) {
    if (is_blank(c)) {
      if (!in_blank) alias += '\x1f';
      in_blank = true;
    } else {
      alias += c;
      in_blank = false;
    }
  }
  return alias;
}

namespace {

// Face corners' position indices against the positions the file defines: a
// negative index counts back from the positions defined so far, a positive
// one may name a position defined further down (tinyobj reads them so), so
// the largest is checked once the file is read.
class VertexIndexCheck {
 public:
  void position() { ++positions_; }
  void face(std::string_view rest, std::size_t line) {
    std::size_t at = 0;
    while (at < rest.size()) {
      while (at < rest.size() && is_blank(rest[at])) ++at;
      const std::size_t end = std::min(rest.find_first_of(" \t\r/", at), rest.size());
      if (end > at) check(rest.substr(at, end - at), line);
      at = rest.find_first_of(" \t\r", end);
      if (at == std::string_view::npos) break;
    }
  }
  std::size_t first_bad_line() const {
    if (bad_line_ != 0) return bad_line_;
    return largest_ > positions_ ? largest_line_ : 0;
  }

 private:
  void check(std::string_view token, std::size_t line) {
    long long index = 0;
    const std::errc parsed = std::from_chars(token.data(), token.data() + token.size(), index).ec;
    // A number too long for 64 bits names no position any file has.
    if (parsed == std::errc::result_out_of_range && bad_line_ == 0) bad_line_ = line;
    if (parsed != std::errc{}) return;
    // Negated as unsigned: -LLONG_MIN does not fit a long long.
    const unsigned long long back = 0ULL - static_cast<unsigned long long>(index);
    const bool bad = index == 0 || (index < 0 && back > positions_);
    if (bad && bad_line_ == 0) bad_line_ = line;
    if (index > 0 && static_cast<unsigned long long>(index) > largest_) {
      largest_ = static_cast<unsigned long long>(index);
      largest_line_ = line;
    }
  }

  unsigned long long positions_ = 0;
  unsigned long long largest_ = 0;
  std::size_t largest_line_ = 0;
  std::size_t bad_line_ = 0;
};

}  // namespace

std::string prepare_obj_text(std::string_view text, ObjTextFindings* findings) {
  VertexIndexCheck indices;
  std::size_t line_number = 0;
  std::string out;
  out.reserve(text.size() + text.size() / 64);
  std::size_t pos = 0;
  while (pos < text.size()) {
    // Gather one logical line, following '\' continuations.
    std::string joined;
    std::size_t consumed_lines = 0;
    bool continued = true;
    while (continued && pos < text.size()) {
      const std::size_t nl = text.find('\n', pos);
      const std::size_t end = nl == std::string_view::npos ? text.size() : nl;
      std::string_view piece = text.substr(pos, end - pos);
      pos = nl == std::string_view::npos ? text.size() : nl + 1;
      ++consumed_lines;
      std::string_view body = piece;
      while (!body.empty() && is_blank(body.back())) body.remove_suffix(1);
      continued = !body.empty() && body.back() == '\\' && body.front() != '#';
      if (continued) {
        joined.append(body.substr(0, body.size() - 1));
        joined += ' ';
      } else {
        joined.append(piece);
      }
    }

    std::string_view keyword;
    std::string_view rest;
    std::string_view line(joined);
    const std::size_t first_line = line_number + 1;
    line_number += consumed_lines;
    if (split_statement(line, keyword, rest)) {
      if (keyword == "v") indices.position();
      if (keyword == "f") indices.face(rest, first_line);
      if (keyword == "f" && corner_count(rest) > kMaxEarClippedCorners) {
        const std::string fixed = needs_corner_fix(rest) ? fix_corners(keyword, rest) : std::string(line);
        out += fan_of(std::string_view(fixed).substr(fixed.find('f') + 1));
      } else if ((keyword == "f" || keyword == "l" || keyword == "p") && needs_corner_fix(rest)) {
        out += fix_corners(keyword, rest);
      } else if (keyword == "mtllib" && text::trim(rest).find_first_of(" \t\\") != std::string_view::npos) {
        out += mtllib_line_in_one_piece(rest);
      } else if (keyword == "usemtl" && material_alias(rest) != text::trim(rest)) {
        out += "usemtl ";
        out += material_alias(rest);
      } else {
        out += line;
      }
    } else {
      out += line;
    }
    for (std::size_t i = 0; i < consumed_lines; ++i) out += '\n';
  }
  if (findings) findings->missing_vertex_line = indices.first_bad_line();
  return out;
}

}  // namespace toond::obj_text
