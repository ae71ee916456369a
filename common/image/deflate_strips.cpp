#include "image/deflate_strips.h"

#include <libdeflate.h>
#include <zlib.h>

#include <algorithm>
#include <climits>
#include <stdexcept>

#include "image/run_deflate.h"
#include "parallel/parallel_tasks.h"

namespace toond::image {
namespace {

struct DeflatedStrip {
  std::vector<std::uint8_t> bytes;  // raw deflate, byte-aligned at its end
  std::uint32_t adler = 1;          // Adler-32 of the strip's input alone
  std::size_t input_bytes = 0;
};

// Raw deflate of one strip by zlib, fed a few rows at a time: no zlib header or
// trailer, those belong to the whole stream. Its output grows with what
// deflate writes, a small fraction of the input on toon frames, rather than
// being sized for the worst case: fresh large buffers cost page faults that
// take longer than compressing.
class StripDeflater {
 public:
  explicit StripDeflater(const DeflateSettings& settings) {
    if (deflateInit2(&z_, settings.level, Z_DEFLATED, -MAX_WBITS, 8, settings.strategy) != Z_OK) {
      throw std::runtime_error("png: deflateInit2 failed");
    }
  }
  ~StripDeflater() { deflateEnd(&z_); }
  StripDeflater(const StripDeflater&) = delete;
  StripDeflater& operator=(const StripDeflater&) = delete;

  void add(std::span<const std::uint8_t> input) {
    while (!input.empty()) {
      // avail_in is 32 bits wide: a huge input goes in in pieces.
      const std::size_t piece = std::min<std::size_t>(input.size(), UINT_MAX / 2);
      z_.next_in = const_cast<Bytef*>(input.data());
      z_.avail_in = static_cast<uInt>(piece);
      run(Z_NO_FLUSH);
      input = input.subspan(piece);
    }
  }

  // The last strip finishes the stream; the others end with a sync flush.
  std::vector<std::uint8_t> finish(bool last) {
    run(last ? Z_FINISH : Z_SYNC_FLUSH);
    bytes_.resize(z_.total_out);
    return std::move(bytes_);
  }

 private:
  void run(int flush) {
    for (;;) {
      if (z_.avail_out == 0) make_room();
      const int rc = deflate(&z_, flush);
      if (rc == Z_STREAM_ERROR) throw std::runtime_error("png: deflate failed");
      if (flush == Z_FINISH ? rc == Z_STREAM_END : z_.avail_in == 0 && z_.avail_out > 0) return;
    }
  }

  void make_room() {
    const std::size_t used = bytes_.size();
    bytes_.resize(std::max<std::size_t>(used * 2, 16 * 1024));
    z_.next_out = bytes_.data() + used;
    z_.avail_out = static_cast<uInt>(bytes_.size() - used);
  }

  z_stream z_{};
  std::vector<std::uint8_t> bytes_;
};

// The two-byte zlib header: 32 KiB window, deflate, a level hint as zlib
// itself would write it, and the check bits that make it a multiple of 31.
std::string zlib_header(const DeflateSettings& settings) {
  int level_hint = 3;
  if (settings.method == DeflateMethod::Runs || settings.strategy >= Z_HUFFMAN_ONLY || settings.level < 2) {
    level_hint = 0;
  } else if (settings.level < 6) {
    level_hint = 1;
  } else if (settings.level == 6) {
    level_hint = 2;
  }
  unsigned header = (0x78u << 8) | (static_cast<unsigned>(level_hint) << 6);
  header += 31 - header % 31;
  return {static_cast<char>(header >> 8), static_cast<char>(header & 0xff)};
}

void append_big_endian(std::string& out, uLong value) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<char>((value >> shift) & 0xff));
}

// Rows go to deflate in chunks of about this many bytes: small enough for
// the scratch rows of a filter to stay in cache and off the page-fault path.
constexpr std::size_t kChunkBytes = 64 * 1024;

// Rows [first, end) through the deflater, and the Adler-32 of what went in
// (libdeflate's, which uses the vector unit; zlib's is a byte at a time).
template <typename Deflater>
DeflatedStrip deflate_strip(Deflater& deflater, int first, int end, int rows_per_chunk, bool last,
                            const ScanlineSource& source) {
  DeflatedStrip strip;
  std::vector<std::uint8_t> scratch;
  for (int row = first; row < end; row += rows_per_chunk) {
    const std::span<const std::uint8_t> rows = source(row, std::min(rows_per_chunk, end - row), scratch);
    strip.adler = libdeflate_adler32(strip.adler, rows.data(), rows.size());
    strip.input_bytes += rows.size();
    deflater.add(rows);
  }
  strip.bytes = deflater.finish(last);
  return strip;
}

}  // namespace

std::string deflate_scanlines(int row_count, std::size_t scanline_bytes, const ScanlineSource& source,
                              const DeflateSettings& settings) {
  const int strips = std::clamp(settings.strips, 1, std::max(row_count, 1));
  const int rows_per_chunk =
      static_cast<int>(std::max<std::size_t>(1, kChunkBytes / std::max<std::size_t>(scanline_bytes, 1)));
  std::vector<DeflatedStrip> deflated(static_cast<std::size_t>(strips));
  parallel::run_tasks(strips, settings.threads, [&](int s) {
    const int first = static_cast<int>(static_cast<long long>(row_count) * s / strips);
    const int end = static_cast<int>(static_cast<long long>(row_count) * (s + 1) / strips);
    const bool last = s == strips - 1;
    DeflatedStrip& strip = deflated[static_cast<std::size_t>(s)];
    if (settings.method == DeflateMethod::Runs) {
      RunDeflater deflater(scanline_bytes);
      strip = deflate_strip(deflater, first, end, rows_per_chunk, last, source);
    } else {
      StripDeflater deflater(settings);
      strip = deflate_strip(deflater, first, end, rows_per_chunk, last, source);
    }
  });

  std::size_t total = 6;
  for (const DeflatedStrip& strip : deflated) {
    total += strip.bytes.size();
  }
  std::string stream = zlib_header(settings);
  stream.reserve(total);
  uLong adler = 1;
  for (const DeflatedStrip& strip : deflated) {
    stream.append(reinterpret_cast<const char*>(strip.bytes.data()), strip.bytes.size());
    adler = adler32_combine(adler, strip.adler, static_cast<z_off_t>(strip.input_bytes));
  }
  append_big_endian(stream, adler);
  return stream;
}

}  // namespace toond::image
