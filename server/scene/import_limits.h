#pragma once
// How much one uploaded bundle may make the importer build. The daemon sets
// these from its --max-* flags for uploads; models already in the store are
// re-imported with the defaults of this struct (no count limits), so a later
// restart with lower limits never makes a stored model unreadable.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

#include "scene/import_error.h"

namespace toond::scene {

struct ImportLimits {
  std::size_t max_vertices = std::numeric_limits<std::size_t>::max();   // positions in the file
  std::size_t max_triangles = std::numeric_limits<std::size_t>::max();  // after fan triangulation
  // Per image, from its header, before any pixel memory is allocated.
  std::uint64_t max_texture_pixels = 8192ull * 8192ull;
  // Wall time one import may take (0: no limit). import_bundle turns it into
  // `deadline` when it starts; the importers check the deadline between
  // their stages, so an import over it stops within one stage of it.
  double max_seconds = 0.0;
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
};

// Throws ImportLimitError naming --max-import-seconds when `limits.deadline`
// has passed; `stage` says what the import was doing ("simplifying").
void check_import_time(const ImportLimits& limits, std::string_view stage);

// An upload over one of the daemon's limits. `limit` is the flag that sets it
// ("--max-triangles"), so the answer can name it (422 "limit_exceeded").
class ImportLimitError : public ImportError {
 public:
  ImportLimitError(std::string file, std::string limit, const std::string& message)
      : ImportError(std::move(file), message), limit_(std::move(limit)) {}
  const std::string& limit() const { return limit_; }

 private:
  std::string limit_;
};

}  // namespace toond::scene
