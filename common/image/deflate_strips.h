#pragma once
// One zlib stream (RFC 1950) from PNG scanlines cut into horizontal strips,
// each strip deflated on its own and, when threads are allowed, at the same
// time as the others. Every strip but the last ends with a sync flush, which
// closes its deflate blocks on a byte boundary without marking the stream
// final, so the raw deflate outputs concatenate into one valid stream; the
// Adler-32 of the whole input is combined from the strips' own.
//
// A strip starts with an empty history, so a match cannot reach back into
// the strip above: a few bytes more than one stream would give, for a
// compression time divided by the strip count when cores are free.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace toond::image {

// Runs: run_deflate.h, the fastest on toon frames. Zlib: zlib's search at
// a level, for callers who want the smallest stream or stored blocks.
enum class DeflateMethod { Runs, Zlib };

struct DeflateSettings {
  DeflateMethod method = DeflateMethod::Runs;
  int level = 1;     // zlib's level 0..9 (0: stored blocks)
  int strategy = 0;  // zlib's Z_DEFAULT_STRATEGY, Z_RLE, ...
  int strips = 1;    // how many independent strips, >= 1
  int threads = 1;   // how many of them run at once, >= 1
};

// The scanlines of rows [first_row, first_row + row_count), each already
// filtered and preceded by its filter-type byte. The source may return a
// view of its own memory or fill `scratch` and return a view of it. It is
// asked for a few rows at a time (about 64 KiB), in order within a strip,
// from several threads at once, each with its own scratch.
using ScanlineSource =
    std::function<std::span<const std::uint8_t>(int first_row, int row_count, std::vector<std::uint8_t>& scratch)>;

// The zlib stream of `row_count` scanlines of `scanline_bytes` bytes each
// (filter byte included). Throws std::runtime_error when zlib fails, and
// rethrows what the source throws.
std::string deflate_scanlines(int row_count, std::size_t scanline_bytes, const ScanlineSource& source,
                              const DeflateSettings& settings);

}  // namespace toond::image
