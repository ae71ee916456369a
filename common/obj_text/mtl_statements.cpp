#include "obj_text/mtl_statements.h"

#include <algorithm>

#include "bundle_paths/statement_names.h"
#include "text/trim.h"

namespace toond::obj_text {

std::map<std::string, MtlStatements> mtl_statements(std::string_view mtl) {
  std::map<std::string, MtlStatements> given;
  std::string current;
  std::size_t pos = 0;
  while (pos < mtl.size()) {
    const std::size_t end = std::min(mtl.find_first_of("\r\n", pos), mtl.size());
    const std::string_view line = text::trim(mtl.substr(pos, end - pos));
    pos = end + ((end + 1 < mtl.size() && mtl[end] == '\r' && mtl[end + 1] == '\n') ? 2 : 1);
    if (line.empty()) continue;
    const auto is = [&](std::string_view keyword) {
      return line.starts_with(keyword) && line.size() > keyword.size() &&
             (line[keyword.size()] == ' ' || line[keyword.size()] == '\t');
    };
    const auto texture = [&](std::optional<std::string>& statement, std::size_t keyword_size) {
      const std::string_view rest = line.substr(keyword_size);
      if (!bundle_paths::texture_names(rest).empty()) statement = std::string(rest);
    };
    if (is("newmtl")) {
      current = std::string(line.substr(7));
    } else if (is("Kd")) {
      given[current].kd = true;
    } else if (is("Ns")) {
      given[current].ns = true;
    } else if (is("Ks")) {
      given[current].ks = true;
    } else if (is("d") || is("Tr")) {
      given[current].dissolve = true;
    } else if (is("illum")) {
      given[current].illum = true;
    } else if (is("map_d")) {
      texture(given[current].map_d, 5);
    } else if (is("map_Kd")) {
      texture(given[current].map_kd, 6);
    } else if (is("map_Bump") || is("map_bump")) {
      texture(given[current].bump, 8);
    } else if (is("bump")) {
      texture(given[current].bump, 4);
    } else if (is("norm")) {
      texture(given[current].norm, 4);
    }
  }
  return given;
}

}  // namespace toond::obj_text
