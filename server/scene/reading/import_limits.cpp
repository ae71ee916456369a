#include "scene/reading/import_limits.h"

#include <cstdio>
#include <limits>

namespace toond::scene {
namespace {

// A count as a whole number; seconds as typed ("0.001 s"), without the
// trailing zeros std::to_string would add.
std::string allowed_text(ImportLimit limit, double allowed) {
  char text[40];
  if (limit == ImportLimit::Seconds) {
    std::snprintf(text, sizeof text, "%g s", allowed);
  } else {
    std::snprintf(text, sizeof text, "%.0f", allowed);
  }
  return text;
}

}  // namespace

ImportLimitError::ImportLimitError(std::string file, ImportLimit limit, double allowed, std::string excess,
                                   std::string after)
    : ImportError(std::move(file), excess + " the limit of " + allowed_text(limit, allowed) + after),
      limit_(limit),
      allowed_(allowed),
      excess_(std::move(excess)),
      after_(std::move(after)) {}

std::string ImportLimitError::message_naming(std::string_view name) const {
  return excess_ + " the limit " + std::string(name) + " = " + allowed_text(limit_, allowed_) + after_;
}

void check_import_time(const ImportLimits& limits, std::string_view stage) {
  if (std::chrono::steady_clock::now() < limits.deadline) return;
  throw ImportLimitError("", ImportLimit::Seconds, limits.max_seconds, "the import took longer than",
                         " and was abandoned while " + std::string(stage) + "; nothing was stored");
}

}  // namespace toond::scene
