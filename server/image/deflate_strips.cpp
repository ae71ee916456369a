#include "image/deflate_strips.h"

#include <zlib.h>

#include <algorithm>
#include <climits>
#include <stdexcept>
#include <thread>

namespace toond::image {
namespace {

struct DeflatedStrip {
  std::vector<std::uint8_t> bytes;  // raw deflate, byte-aligned at its end
  uLong adler = 1;                  // Adler-32 of the strip's input alone
  std::size_t input_bytes = 0;
  std::string error;                // empty: fine
};

// Raw deflate of one strip: no zlib header or trailer, those belong to the
// whole stream. The last strip finishes the stream; the others sync-flush.
DeflatedStrip deflate_strip(std::span<const std::uint8_t> input, const DeflateSettings& settings, bool last) {
  DeflatedStrip strip;
  strip.input_bytes = input.size();
  strip.adler = adler32_z(1, input.data(), input.size());
  z_stream z{};
  if (deflateInit2(&z, settings.level, Z_DEFLATED, -MAX_WBITS, 8, settings.strategy) != Z_OK) {
    strip.error = "deflateInit2 failed";
    return strip;
  }
  strip.bytes.resize(deflateBound(&z, input.size()) + 16);
  z.next_out = strip.bytes.data();
  z.avail_out = static_cast<uInt>(strip.bytes.size());
  std::size_t fed = 0;
  const int end_flush = last ? Z_FINISH : Z_SYNC_FLUSH;
  for (;;) {
    if (z.avail_in == 0 && fed < input.size()) {
      // avail_in is 32 bits wide: a huge strip goes in in pieces.
      const std::size_t piece = std::min<std::size_t>(input.size() - fed, UINT_MAX / 2);
      z.next_in = const_cast<Bytef*>(input.data() + fed);
      z.avail_in = static_cast<uInt>(piece);
      fed += piece;
    }
    if (z.avail_out == 0) {
      const std::size_t used = strip.bytes.size();
      strip.bytes.resize(used * 2);
      z.next_out = strip.bytes.data() + used;
      z.avail_out = static_cast<uInt>(strip.bytes.size() - used);
    }
    const int flush = fed == input.size() ? end_flush : Z_NO_FLUSH;
    const int rc = deflate(&z, flush);
    if (rc == Z_STREAM_ERROR) {
      strip.error = "deflate failed";
      break;
    }
    if (flush == Z_FINISH && rc == Z_STREAM_END) break;
    // A sync flush is complete once deflate returns with output room left.
    if (flush == Z_SYNC_FLUSH && z.avail_in == 0 && z.avail_out > 0) break;
  }
  strip.bytes.resize(z.total_out);
  deflateEnd(&z);
  return strip;
}

// The two-byte zlib header: 32 KiB window, deflate, a level hint as zlib
// itself would write it, and the check bits that make it a multiple of 31.
std::string zlib_header(const DeflateSettings& settings) {
  int level_hint = 3;
  if (settings.strategy >= Z_HUFFMAN_ONLY || settings.level < 2) {
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

}  // namespace

std::string deflate_scanlines(int row_count, const ScanlineSource& source, const DeflateSettings& settings) {
  const int strips = std::clamp(settings.strips, 1, std::max(row_count, 1));
  const int threads = std::clamp(settings.threads, 1, strips);
  std::vector<DeflatedStrip> deflated(static_cast<std::size_t>(strips));

  // Worker w takes strips w, w + threads, ...; the calling thread is worker 0.
  auto work = [&](int worker) {
    std::vector<std::uint8_t> scratch;
    for (int s = worker; s < strips; s += threads) {
      const int first = static_cast<int>(static_cast<long long>(row_count) * s / strips);
      const int end = static_cast<int>(static_cast<long long>(row_count) * (s + 1) / strips);
      try {
        deflated[static_cast<std::size_t>(s)] = deflate_strip(source(first, end - first, scratch), settings, s == strips - 1);
      } catch (const std::exception& e) {
        deflated[static_cast<std::size_t>(s)].error = e.what();
      }
    }
  };
  {
    std::vector<std::jthread> helpers;
    helpers.reserve(static_cast<std::size_t>(threads - 1));
    for (int w = 1; w < threads; ++w) helpers.emplace_back(work, w);
    work(0);
  }

  std::size_t total = 6;
  for (const DeflatedStrip& strip : deflated) {
    if (!strip.error.empty()) throw std::runtime_error("png: " + strip.error);
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
