#pragma once
// The daemon's flag for each limit the importer reports by kind: the words
// of an import-limit answer belong here, beside the flags, not in scene/.
#include <string_view>

#include "scene/reading/import_limits.h"

namespace toond::http {

// "--max-vertices" for ImportLimit::Vertices, and so on.
std::string_view import_limit_flag(scene::ImportLimit limit);

}  // namespace toond::http
