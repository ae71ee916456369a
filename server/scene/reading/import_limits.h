#pragma once
// How much one uploaded bundle may make the importer build. The daemon sets
// these from its flags for uploads; models already in the store are
// re-imported with the defaults of this struct (no count limits), so a later
// restart with lower limits never makes a stored model unreadable.
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

#include "scene/reading/import_error.h"

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

// Throws ImportLimitError (ImportLimit::Seconds) when `limits.deadline` has
// passed; `stage` says what the import was doing ("simplifying").
void check_import_time(const ImportLimits& limits, std::string_view stage);

// Which of ImportLimits an import went over. What sets each one (the
// daemon's flags) is the caller's business, so an error names the limit by
// this and never by a flag.
enum class ImportLimit { Vertices, Triangles, TexturePixels, Seconds };

// An upload over one of its ImportLimits (the daemon answers 422
// "limit_exceeded"). The message is kept in its parts so that a caller can
// name the limit in its own words: `excess` says what went over and how far
// ("m.obj has 5001 triangles, more than"), `allowed` is the limit's value
// (seconds for ImportLimit::Seconds, else a count), `after` is what follows
// ("; nothing was stored"). what() reads "<excess> the limit of
// <allowed><after>".
class ImportLimitError : public ImportError {
 public:
  ImportLimitError(std::string file, ImportLimit limit, double allowed, std::string excess, std::string after = {});

  ImportLimit limit() const { return limit_; }
  double allowed() const { return allowed_; }
  // The message with the limit called `name`: "<excess> the limit <name> =
  // <allowed><after>".
  std::string message_naming(std::string_view name) const;

 private:
  ImportLimit limit_;
  double allowed_;
  std::string excess_;
  std::string after_;
};

}  // namespace toond::scene
