#pragma once
// A deflate encoder (RFC 1951) made for the scanlines of toon frames, which
// are long runs of one byte (a flat band is zeros after the Sub filter, one
// index in a palette frame) broken by short stretches of edge pixels. The
// only match it looks for is a run of the byte before (distance 1); every
// other byte is a literal. That finds nearly what zlib's fastest search
// finds on these frames, with one compare a byte where zlib hashes, chains
// and slides a window, and the Huffman codes are made for the strip's own
// symbol counts, so the stream is as tight as a dynamic block can make it.
//
// A strip is one dynamic block. Every strip but the last ends with an empty
// stored block, which brings it to a byte boundary without ending the
// stream, so strips encoded apart concatenate into one raw deflate stream.
// A strip's first byte never refers to the strip above.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace toond::image {

class RunDeflater {
 public:
  // `row_bytes`: the scanline's length. A stretch that repeats the row
  // above (a vertical edge) of at least four bytes is sent as a copy from
  // that distance; 0, or a row longer than deflate's 32 KiB window, sends
  // only runs and literals.
  explicit RunDeflater(std::size_t row_bytes = 0);
  ~RunDeflater();
  RunDeflater(const RunDeflater&) = delete;
  RunDeflater& operator=(const RunDeflater&) = delete;

  // Adds the strip's next bytes; a run may go on from one call to the next.
  void add(std::span<const std::uint8_t> input);
  // The strip's raw deflate bytes. `last`: the block ends the stream.
  std::vector<std::uint8_t> finish(bool last);

  // Lit/length symbols of deflate: 256 literals, end of block, 29 lengths.
  static constexpr int kSymbols = 286;

 private:
  // Writes a run of `run` more copies of `byte` (lengths, or literals when
  // under three) at `out`, counts its symbols, and returns the end.
  std::uint16_t* put_run(std::uint16_t* out, int byte, std::size_t run);

  // The strip as tokens: a literal is its byte (0..255), a run of n bytes
  // 256 + n (n 3..258), a copy of n bytes from the row above 515 + n
  // (n 4..258); and how often each lit/length symbol occurs in them.
  std::vector<std::uint16_t> tokens_;
  std::array<std::uint32_t, kSymbols> counts_{};
  std::size_t copies_ = 0;  // copy tokens, whose distance adds to the size
  std::size_t row_bytes_ = 0;
  int previous_ = -1;            // the last byte sent, -1 before the first
  std::size_t pending_run_ = 0;  // copies of it since, not yet tokens: a run
                                 // may go on in the next add()
};

}  // namespace toond::image
