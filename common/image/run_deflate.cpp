#include "image/run_deflate.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <utility>

namespace toond::image {
namespace {

constexpr int kEndOfBlock = 256;
constexpr int kMinRun = 3;
constexpr int kMaxRun = 258;
constexpr int kMaxCodeBits = 15;
constexpr int kMaxCodeLengthBits = 7;
// The run's distance, 1, is distance code 0. A second, unused code makes
// the distance code complete (two codes of one bit), which every inflater
// accepts; a lone one-bit code is a special case some reject.
constexpr int kDistanceCodes = 2;
// A copy of the row above is worth its length, distance and their extra
// bits (about 20 bits for a 512-pixel RGB row) from this many bytes on.
constexpr std::size_t kMinCopy = 4;
// Deflate's window: a row longer than this cannot be copied from.
constexpr std::size_t kWindow = 32768;
// Token values: a literal is its byte, a run of n bytes kRunToken + n, a
// copy of n bytes from the row above kCopyToken + n.
constexpr int kRunToken = 256;
constexpr int kCopyToken = kRunToken + kMaxRun + 1;

// Deflate's length symbols: the first length of each, and its extra bits.
struct LengthSymbol {
  std::uint16_t symbol;
  std::uint8_t extra_bits;
  std::uint16_t extra_value;
};

constexpr std::array<LengthSymbol, kMaxRun + 1> make_length_table() {
  constexpr std::array<int, 29> base = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                        31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
  constexpr std::array<int, 29> extra = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                         2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
  std::array<LengthSymbol, kMaxRun + 1> table{};
  for (int code = 0; code < 29; ++code) {
    const int end = code + 1 < 29 ? base[code + 1] : kMaxRun + 1;
    for (int length = base[code]; length < end; ++length) {
      table[length] = {static_cast<std::uint16_t>(257 + code), static_cast<std::uint8_t>(extra[code]),
                       static_cast<std::uint16_t>(length - base[code])};
    }
  }
  return table;
}
constexpr std::array<LengthSymbol, kMaxRun + 1> kLengths = make_length_table();

// The extra bits after lit/length symbol s (257..285).
constexpr int length_extra_bits(int s) { return s < 265 || s == 285 ? 0 : (s - 261) / 4; }

// Deflate's distance code for a distance, its extra bits and their value.
struct DistanceSymbol {
  int symbol;
  int extra_bits;
  std::uint32_t extra_value;
};

constexpr DistanceSymbol distance_symbol(std::size_t distance) {
  if (distance <= 4) return {static_cast<int>(distance) - 1, 0, 0};
  // From code 4 on, each pair of codes covers twice the distances of the
  // pair before: 5-6, 7-8, 9-12, 13-16, ...
  const std::size_t v = distance - 1;
  const int top = static_cast<int>(std::bit_width(v)) - 1;
  const int extra = top - 1;
  const int symbol = 2 * top + static_cast<int>((v >> extra) & 1u);
  const std::size_t base = (std::size_t{2} + static_cast<std::size_t>(symbol & 1)) << extra;
  return {symbol, extra, static_cast<std::uint32_t>(v - base)};
}

// How many of the first n bytes at a and b agree.
std::size_t common_prefix(const std::uint8_t* a, const std::uint8_t* b, std::size_t n) {
  std::size_t i = 0;
  if constexpr (std::endian::native == std::endian::little) {
    for (; i + 8 <= n; i += 8) {
      std::uint64_t x;
      std::uint64_t y;
      std::memcpy(&x, a + i, 8);
      std::memcpy(&y, b + i, 8);
      if (const std::uint64_t differ = x ^ y) return i + static_cast<std::size_t>(std::countr_zero(differ) / 8);
    }
  }
  while (i < n && a[i] == b[i]) ++i;
  return i;
}

// How many of the first n bytes at p equal b.
std::size_t run_of(const std::uint8_t* p, std::size_t n, std::uint8_t b) {
  std::size_t i = 0;
  if constexpr (std::endian::native == std::endian::little) {
    const std::uint64_t pattern = 0x0101010101010101ull * b;
    for (; i + 8 <= n; i += 8) {
      std::uint64_t word;
      std::memcpy(&word, p + i, 8);
      if (const std::uint64_t differ = word ^ pattern)
        return i + static_cast<std::size_t>(std::countr_zero(differ) / 8);
    }
  }
  while (i < n && p[i] == b) ++i;
  return i;
}

// Optimal code lengths for weights sorted in ascending order, worked out in
// place in three sweeps over the array (the sorted-weights method: merged
// nodes are made in ascending order too, so two cursors replace a heap).
// On return w[i] is the length of the i-th lightest symbol's code.
void sorted_code_lengths(std::vector<std::uint64_t>& w) {
  const int n = static_cast<int>(w.size());
  // Sweep 1: w[k] becomes the k-th merged node's weight, and once a merged
  // node has been merged itself, the index of its parent.
  w[0] += w[1];
  int merged = 0;  // the lightest merged node not yet merged again
  int leaf = 2;    // the lightest leaf not yet merged
  auto take_lighter = [&](int k) -> std::uint64_t {
    if (leaf >= n || (merged < k && w[static_cast<std::size_t>(merged)] < w[static_cast<std::size_t>(leaf)])) {
      const std::uint64_t weight = w[static_cast<std::size_t>(merged)];
      w[static_cast<std::size_t>(merged++)] = static_cast<std::uint64_t>(k);
      return weight;
    }
    return w[static_cast<std::size_t>(leaf++)];
  };
  for (int k = 1; k < n - 1; ++k) {
    const std::uint64_t first = take_lighter(k);
    w[static_cast<std::size_t>(k)] = first + take_lighter(k);
  }
  // Sweep 2: each merged node's depth, from the root (node n-2) down.
  w[static_cast<std::size_t>(n - 2)] = 0;
  for (int k = n - 3; k >= 0; --k) w[static_cast<std::size_t>(k)] = w[w[static_cast<std::size_t>(k)]] + 1;
  // Sweep 3: the leaves' depths, deepest leaves last-filled from the right.
  int free_slots = 1;
  int internal = 0;
  std::uint64_t depth = 0;
  int node = n - 2;
  int next = n - 1;
  while (free_slots > 0) {
    while (node >= 0 && w[static_cast<std::size_t>(node)] == depth) {
      ++internal;
      --node;
    }
    for (; free_slots > internal; --free_slots) w[static_cast<std::size_t>(next--)] = depth;
    free_slots = 2 * internal;
    ++depth;
    internal = 0;
  }
}

// Huffman code lengths for the counts (0: symbol unused, no code), none
// longer than max_bits; at least two symbols must be used. When the optimal
// code is too deep the counts are halved (a used symbol keeps at least 1)
// until it fits, which flattens the code a little.
std::vector<std::uint8_t> code_lengths(std::span<const std::uint32_t> counts, int max_bits) {
  std::vector<int> symbols;
  for (std::size_t s = 0; s < counts.size(); ++s) {
    if (counts[s] > 0) symbols.push_back(static_cast<int>(s));
  }
  std::vector<std::uint64_t> weights(counts.begin(), counts.end());
  std::vector<std::uint8_t> lengths(counts.size(), 0);
  std::vector<std::uint64_t> sorted(symbols.size());
  for (;;) {
    std::stable_sort(symbols.begin(), symbols.end(), [&](int a, int b) {
      return weights[static_cast<std::size_t>(a)] < weights[static_cast<std::size_t>(b)];
    });
    for (std::size_t i = 0; i < symbols.size(); ++i) sorted[i] = weights[static_cast<std::size_t>(symbols[i])];
    sorted_code_lengths(sorted);
    if (sorted.front() <= static_cast<std::uint64_t>(max_bits)) break;
    for (std::uint64_t& w : weights) {
      if (w > 0) w = std::max<std::uint64_t>(1, w / 2);
    }
  }
  for (std::size_t i = 0; i < symbols.size(); ++i) {
    lengths[static_cast<std::size_t>(symbols[i])] = static_cast<std::uint8_t>(sorted[i]);
  }
  return lengths;
}

constexpr std::array<std::uint8_t, 256> kReversedBytes = [] {
  std::array<std::uint8_t, 256> table{};
  for (unsigned b = 0; b < 256; ++b) {
    unsigned r = 0;
    for (int bit = 0; bit < 8; ++bit) r |= ((b >> bit) & 1u) << (7 - bit);
    table[b] = static_cast<std::uint8_t>(r);
  }
  return table;
}();

// The canonical code of each length, bit-reversed: deflate sends a Huffman
// code from its top bit, and the writer fills bytes from their low bit.
std::vector<std::uint16_t> canonical_codes(std::span<const std::uint8_t> lengths) {
  std::array<int, kMaxCodeBits + 2> per_length{};
  for (const std::uint8_t length : lengths) ++per_length[length];
  per_length[0] = 0;
  std::array<int, kMaxCodeBits + 2> next{};
  for (int bits = 1, code = 0; bits <= kMaxCodeBits; ++bits) {
    code = (code + per_length[bits - 1]) << 1;
    next[bits] = code;
  }
  std::vector<std::uint16_t> codes(lengths.size(), 0);
  for (std::size_t s = 0; s < lengths.size(); ++s) {
    const int length = lengths[s];
    if (length == 0) continue;
    const unsigned code = static_cast<unsigned>(next[length]++);
    const unsigned reversed = static_cast<unsigned>(kReversedBytes[code & 0xff]) << 8 | kReversedBytes[code >> 8];
    codes[s] = static_cast<std::uint16_t>(reversed >> (16 - length));
  }
  return codes;
}

struct HuffmanCode {
  std::vector<std::uint8_t> lengths;
  std::vector<std::uint16_t> codes;
};

HuffmanCode huffman_code(std::span<const std::uint32_t> counts, int max_bits) {
  HuffmanCode code{code_lengths(counts, max_bits), {}};
  code.codes = canonical_codes(code.lengths);
  return code;
}

// Fills bytes from their low bit, as deflate packs them, into a buffer the
// caller has sized for every bit it puts.
class BitWriter {
 public:
  explicit BitWriter(std::vector<std::uint8_t>& out) : out_(out) {}

  void put(std::uint32_t value, int bits) {
    pending_ |= static_cast<std::uint64_t>(value) << pending_bits_;
    pending_bits_ += bits;
    if (pending_bits_ >= 32) {
      store(4);
      pending_ >>= 32;
      pending_bits_ -= 32;
    }
  }
  void put(const HuffmanCode& code, int symbol) {
    put(code.codes[static_cast<std::size_t>(symbol)], code.lengths[static_cast<std::size_t>(symbol)]);
  }
  // Pads to a byte boundary and returns the bytes written.
  std::size_t flush() {
    const int bytes = (pending_bits_ + 7) / 8;
    store(bytes);
    pending_ = 0;
    pending_bits_ = 0;
    return written_;
  }

 private:
  void store(int bytes) {
    for (int b = 0; b < bytes; ++b)
      out_[written_ + static_cast<std::size_t>(b)] = static_cast<std::uint8_t>(pending_ >> (8 * b));
    written_ += static_cast<std::size_t>(bytes);
  }

  std::vector<std::uint8_t>& out_;
  std::uint64_t pending_ = 0;
  int pending_bits_ = 0;
  std::size_t written_ = 0;
};

// One symbol of the code-length alphabet: a length 0..15 or a repeat
// (16: the last length 3-6 times, 17: zeros 3-10 times, 18: zeros 11-138).
struct LengthToken {
  std::uint8_t symbol;
  std::uint8_t extra;
};

// The lit/length and distance code lengths, one sequence, with runs folded
// into repeat symbols as deflate's block header allows.
std::vector<LengthToken> fold_lengths(std::span<const std::uint8_t> lengths) {
  std::vector<LengthToken> tokens;
  for (std::size_t i = 0; i < lengths.size();) {
    const std::uint8_t value = lengths[i];
    std::size_t run = 1;
    while (i + run < lengths.size() && lengths[i + run] == value) ++run;
    i += run;
    if (value == 0) {
      for (; run >= 11; run -= std::min<std::size_t>(run, 138)) {
        tokens.push_back({18, static_cast<std::uint8_t>(std::min<std::size_t>(run, 138) - 11)});
      }
      if (run >= 3) {
        tokens.push_back({17, static_cast<std::uint8_t>(run - 3)});
        run = 0;
      }
    } else {
      tokens.push_back({value, 0});
      --run;
      for (; run >= 3; run -= std::min<std::size_t>(run, 6)) {
        tokens.push_back({16, static_cast<std::uint8_t>(std::min<std::size_t>(run, 6) - 3)});
      }
    }
    for (; run > 0; --run) tokens.push_back({value, 0});
  }
  return tokens;
}

int extra_bits_of(std::uint8_t length_symbol) {
  switch (length_symbol) {
    case 16:
      return 2;
    case 17:
      return 3;
    case 18:
      return 7;
    default:
      return 0;
  }
}

// The order deflate sends the code-length code's own lengths in.
constexpr std::array<int, 19> kCodeLengthOrder = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};

// Everything between the block type and the first data symbol: the counts
// of codes, the code-length code, and the two codes' lengths folded by it.
class BlockHeader {
 public:
  BlockHeader(const HuffmanCode& literals, int literal_count, const HuffmanCode& distances) {
    std::vector<std::uint8_t> lengths(literals.lengths.begin(), literals.lengths.begin() + literal_count);
    lengths.insert(lengths.end(), distances.lengths.begin(), distances.lengths.end());
    tokens_ = fold_lengths(lengths);
    std::array<std::uint32_t, 19> counts{};
    for (const LengthToken& t : tokens_) ++counts[t.symbol];
    code_ = huffman_code(counts, kMaxCodeLengthBits);
    order_count_ = 19;
    while (order_count_ > 4 && code_.lengths[static_cast<std::size_t>(kCodeLengthOrder[order_count_ - 1])] == 0) {
      --order_count_;
    }
    literal_count_ = literal_count;
    distance_count_ = static_cast<int>(distances.lengths.size());
  }

  std::size_t bits() const {
    std::size_t bits = 5 + 5 + 4 + 3 * static_cast<std::size_t>(order_count_);
    for (const LengthToken& t : tokens_)
      bits += code_.lengths[t.symbol] + static_cast<std::size_t>(extra_bits_of(t.symbol));
    return bits;
  }

  void write(BitWriter& out) const {
    out.put(static_cast<std::uint32_t>(literal_count_ - 257), 5);
    out.put(static_cast<std::uint32_t>(distance_count_ - 1), 5);
    out.put(static_cast<std::uint32_t>(order_count_ - 4), 4);
    for (int i = 0; i < order_count_; ++i) out.put(code_.lengths[static_cast<std::size_t>(kCodeLengthOrder[i])], 3);
    for (const LengthToken& t : tokens_) {
      out.put(code_, t.symbol);
      if (const int extra = extra_bits_of(t.symbol)) out.put(t.extra, extra);
    }
  }

 private:
  std::vector<LengthToken> tokens_;
  HuffmanCode code_;
  int order_count_ = 19;
  int literal_count_ = 257;
  int distance_count_ = kDistanceCodes;
};

// What a token puts in the stream, in one go: a literal's code, or a run's
// or a copy's length code, its extra bits and, for a run, the distance
// code (at most 15 + 5 + 15 bits). A copy's distance goes out after it.
struct TokenBits {
  std::uint32_t bits = 0;
  int count = 0;
};

std::vector<TokenBits> bits_of_tokens(const HuffmanCode& literals, const HuffmanCode& distances) {
  std::vector<TokenBits> table(kCopyToken + kMaxRun + 1);
  for (int byte = 0; byte < 256; ++byte) {
    table[static_cast<std::size_t>(byte)] = {literals.codes[static_cast<std::size_t>(byte)],
                                             literals.lengths[static_cast<std::size_t>(byte)]};
  }
  for (int length = kMinRun; length <= kMaxRun; ++length) {
    const LengthSymbol& l = kLengths[static_cast<std::size_t>(length)];
    TokenBits& t = table[static_cast<std::size_t>(256 + length)];
    t.bits = literals.codes[l.symbol];
    t.count = literals.lengths[l.symbol];
    t.bits |= static_cast<std::uint32_t>(l.extra_value) << t.count;
    t.count += l.extra_bits;
    table[static_cast<std::size_t>(kCopyToken + length)] = t;
    t.bits |= static_cast<std::uint32_t>(distances.codes[0]) << t.count;
    t.count += distances.lengths[0];
  }
  return table;
}

// The token buffers of finished strips, kept per thread so that the next
// frame's strips write into pages already mapped.
thread_local std::vector<std::uint16_t> spare_tokens;
// Past this many tokens (a very large frame) the buffer is given back.
constexpr std::size_t kMaxSpareTokens = std::size_t{4} << 20;

}  // namespace

RunDeflater::RunDeflater(std::size_t row_bytes)
    : row_bytes_(row_bytes >= kMinCopy && row_bytes <= kWindow ? row_bytes : 0) {
  tokens_.swap(spare_tokens);
  tokens_.clear();
  // Both codes need two used symbols to be complete; the end of block is one.
  counts_[0] = 1;
  counts_[kEndOfBlock] = 1;
}

RunDeflater::~RunDeflater() {
  if (tokens_.capacity() <= kMaxSpareTokens) tokens_.swap(spare_tokens);
}

void RunDeflater::add(std::span<const std::uint8_t> input) {
  const std::uint8_t* p = input.data();
  const std::size_t n = input.size();
  // At most one token a byte, and the tokens of the run carried over from
  // the last add: room for all of them up front, so the loop writes through
  // a pointer with no capacity check.
  const std::size_t used = tokens_.size();
  tokens_.resize(used + n + pending_run_ / kMaxRun + 2);
  std::uint16_t* out = tokens_.data() + used;
  int previous = previous_;
  std::size_t pending = pending_run_;
  for (std::size_t i = 0; i < n;) {
    if (p[i] == previous) {
      const std::size_t run = run_of(p + i, n - i, p[i]);
      pending += run;
      i += run;
      continue;
    }
    if (pending > 0) {
      out = put_run(out, previous, pending);
      pending = 0;
    }
    if (row_bytes_ > 0 && i >= row_bytes_ && p[i] == p[i - row_bytes_]) {
      const std::size_t copy = common_prefix(p + i, p + i - row_bytes_, std::min<std::size_t>(n - i, kMaxRun));
      if (copy >= kMinCopy) {
        *out++ = static_cast<std::uint16_t>(kCopyToken + copy);
        ++counts_[kLengths[copy].symbol];
        ++copies_;
        i += copy;
        previous = p[i - 1];
        continue;
      }
    }
    previous = p[i];
    *out++ = p[i];
    ++counts_[p[i]];
    ++i;
  }
  previous_ = previous;
  pending_run_ = pending;
  tokens_.resize(static_cast<std::size_t>(out - tokens_.data()));
}

std::uint16_t* RunDeflater::put_run(std::uint16_t* out, int byte, std::size_t run) {
  for (; run >= kMinRun + kMaxRun || run == kMaxRun; run -= kMaxRun) {
    *out++ = static_cast<std::uint16_t>(kRunToken + kMaxRun);
    ++counts_[kLengths[kMaxRun].symbol];
  }
  // What is left is one more length, or two when one would be too long,
  // split so that neither is under three; under three bytes are literals.
  if (run > kMaxRun) {
    *out++ = static_cast<std::uint16_t>(kRunToken + run - kMinRun);
    ++counts_[kLengths[run - kMinRun].symbol];
    run = kMinRun;
  }
  if (run >= kMinRun) {
    *out++ = static_cast<std::uint16_t>(kRunToken + run);
    ++counts_[kLengths[run].symbol];
    return out;
  }
  for (; run > 0; --run) {
    *out++ = static_cast<std::uint16_t>(byte);
    ++counts_[static_cast<std::size_t>(byte)];
  }
  return out;
}

std::vector<std::uint8_t> RunDeflater::finish(bool last) {
  // The run the input ended in; a run is at most 2 tokens per 258 bytes.
  const std::size_t used = tokens_.size();
  tokens_.resize(used + pending_run_ / kMaxRun + 2);
  tokens_.resize(static_cast<std::size_t>(put_run(tokens_.data() + used, previous_, pending_run_) - tokens_.data()));
  pending_run_ = 0;
  const HuffmanCode literals = huffman_code(counts_, kMaxCodeBits);
  int literal_count = kSymbols;
  while (literal_count > 257 && literals.lengths[static_cast<std::size_t>(literal_count - 1)] == 0) --literal_count;
  // Two distances, each a one-bit code: 1 (runs) and the row's length
  // (copies), or an unused second code when copies are off.
  const DistanceSymbol row = distance_symbol(row_bytes_ > 0 ? row_bytes_ : 2);
  std::vector<std::uint32_t> distance_counts(static_cast<std::size_t>(std::max(row.symbol + 1, kDistanceCodes)), 0);
  distance_counts[0] = distance_counts[static_cast<std::size_t>(row.symbol)] = 1;
  const HuffmanCode distances = huffman_code(distance_counts, kMaxCodeBits);
  const std::uint32_t copy_distance = distances.codes[static_cast<std::size_t>(row.symbol)] |
                                      row.extra_value << distances.lengths[static_cast<std::size_t>(row.symbol)];
  const int copy_distance_bits = distances.lengths[static_cast<std::size_t>(row.symbol)] + row.extra_bits;
  const BlockHeader header(literals, literal_count, distances);
  const std::vector<TokenBits> token_bits = bits_of_tokens(literals, distances);

  // The block's size (a few bits over: the two counts set at the start),
  // then the strip's end, so that every put below has room.
  std::size_t bits = 3 + header.bits() + literals.lengths[kEndOfBlock];
  for (int s = 0; s < kSymbols; ++s) {
    const std::size_t count = counts_[static_cast<std::size_t>(s)];
    bits += count * literals.lengths[static_cast<std::size_t>(s)];
    if (s > kEndOfBlock) bits += count * static_cast<std::size_t>(length_extra_bits(s) + distances.lengths[0]);
  }
  bits += copies_ * static_cast<std::size_t>(copy_distance_bits);
  constexpr std::size_t kStripEndBits = 3 + 7 + 32;
  std::vector<std::uint8_t> out((bits + kStripEndBits) / 8 + 8);

  BitWriter writer(out);
  writer.put(last ? 1u : 0u, 1);
  writer.put(2, 2);  // dynamic Huffman codes
  header.write(writer);
  for (const std::uint16_t token : tokens_) {
    writer.put(token_bits[token].bits, token_bits[token].count);
    if (token > kCopyToken) writer.put(copy_distance, copy_distance_bits);
  }
  writer.put(literals, kEndOfBlock);
  if (!last) {
    writer.put(0, 3);  // an empty stored block, not final: aligns the strip's end
    writer.flush();
    writer.put(0xffff0000u, 32);
  }
  out.resize(writer.flush());
  return out;
}

}  // namespace toond::image
