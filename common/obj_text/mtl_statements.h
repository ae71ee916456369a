#pragma once
// Which statements an MTL gives each material, where tinyobjloader's
// defaults cannot be told apart from values written in the file (it makes
// up Kd 0.6 beside a map_Kd, Ns 1, ...), and the texture statements as
// written: tinyobj's option parser reads the name as a number after -o, -s
// or -t with fewer than three numbers, while bundle_paths::texture_names
// (the reading `toon` sends files by) does not.
#include <map>
#include <optional>
#include <string>
#include <string_view>

namespace toond::obj_text {

struct MtlStatements {
  bool kd = false;
  bool ns = false;
  bool ks = false;
  bool dissolve = false;  // d or Tr
  bool illum = false;
  std::optional<std::string> map_kd;  // the text after the keyword
  std::optional<std::string> map_d;
  std::optional<std::string> bump;  // map_Bump, map_bump or bump
  std::optional<std::string> norm;
};

// The statements given per material name in an MTL text. Lines, names and
// keywords are cut exactly as tinyobj's LoadMtl cuts them (any of \n, \r\n,
// \r ends a line; the name is the rest of the newmtl line less trailing
// blanks; keywords are case-sensitive), so the names match the ones it
// produced and the same statements count. As in tinyobj, a texture
// statement that names no file leaves the one before.
std::map<std::string, MtlStatements> mtl_statements(std::string_view mtl);

}  // namespace toond::obj_text
