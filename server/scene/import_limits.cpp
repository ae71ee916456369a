#include "scene/import_limits.h"

#include <cstdio>

namespace toond::scene {

void check_import_time(const ImportLimits& limits, std::string_view stage) {
  if (std::chrono::steady_clock::now() < limits.deadline) return;
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%g", limits.max_seconds);
  throw ImportLimitError("", "--max-import-seconds",
                         "the import took longer than the limit --max-import-seconds = " + std::string(seconds) +
                             " s and was abandoned while " + std::string(stage) + "; nothing was stored");
}

}  // namespace toond::scene
