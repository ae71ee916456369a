#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>
#include <random>

#include "image/run_deflate.h"

namespace toond::image {
namespace {

using Bytes = std::vector<std::uint8_t>;

// zlib's inflater on a raw deflate stream; fails the test unless the stream
// ends exactly where its last block says it does.
Bytes inflate_raw(const Bytes& stream, std::size_t expected_size) {
  z_stream z{};
  EXPECT_EQ(inflateInit2(&z, -MAX_WBITS), Z_OK);
  Bytes out(expected_size + 64);
  z.next_in = const_cast<Bytef*>(stream.data());
  z.avail_in = static_cast<uInt>(stream.size());
  z.next_out = out.data();
  z.avail_out = static_cast<uInt>(out.size());
  const int rc = inflate(&z, Z_FINISH);
  EXPECT_EQ(rc, Z_STREAM_END) << (z.msg ? z.msg : "");
  EXPECT_EQ(z.avail_in, 0u) << "bytes left after the final block";
  out.resize(z.total_out);
  inflateEnd(&z);
  return out;
}

Bytes deflate_whole(const Bytes& input) {
  RunDeflater deflater;
  deflater.add(input);
  return deflater.finish(true);
}

TEST(RunDeflate, EveryRunLengthComesBack) {
  // Lengths around each of deflate's length-code boundaries and past the
  // longest match (258), where a run is split.
  for (std::size_t length = 1; length <= 800; ++length) {
    Bytes input = {9, 9, 4};
    input.insert(input.end(), length, 7);
    input.push_back(4);
    input.insert(input.end(), length, 4);
    SCOPED_TRACE(length);
    EXPECT_EQ(inflate_raw(deflate_whole(input), input.size()), input);
  }
}

TEST(RunDeflate, RunsGoOnFromOneAddToTheNext) {
  std::mt19937 random(3);
  Bytes input;
  for (int i = 0; i < 4000; ++i) input.insert(input.end(), random() % 40, static_cast<std::uint8_t>(random() % 3));
  RunDeflater pieces;
  for (std::size_t at = 0; at < input.size();) {
    const std::size_t size = std::min<std::size_t>(1 + random() % 7, input.size() - at);
    pieces.add(std::span<const std::uint8_t>(input).subspan(at, size));
    at += size;
  }
  const Bytes in_pieces = pieces.finish(true);
  EXPECT_EQ(in_pieces, deflate_whole(input)) << "a run cut by an add() is still one run";
  EXPECT_EQ(inflate_raw(in_pieces, input.size()), input);
}

TEST(RunDeflate, FlatBandsCostAlmostNothing) {
  const Bytes zeros(1 << 20, 0);
  const Bytes stream = deflate_whole(zeros);
  EXPECT_LT(stream.size(), 1200u) << "a megabyte of one byte is runs of 258 at one or two bits each";
  EXPECT_EQ(inflate_raw(stream, zeros.size()), zeros);
}

TEST(RunDeflate, ARowThatRepeatsTheRowAboveIsACopy) {
  // Rows of noise, each repeated once: without copies every byte of the
  // repeat would be a literal.
  constexpr std::size_t kRow = 300;
  std::mt19937 random(2);
  Bytes input;
  for (int r = 0; r < 20; ++r) {
    Bytes row(kRow);
    for (std::uint8_t& b : row) b = static_cast<std::uint8_t>(random());
    input.insert(input.end(), row.begin(), row.end());
    input.insert(input.end(), row.begin(), row.end());
  }
  RunDeflater with_copies(kRow);
  with_copies.add(input);
  const Bytes copied = with_copies.finish(true);
  EXPECT_EQ(inflate_raw(copied, input.size()), input);
  EXPECT_LT(copied.size(), input.size() * 6 / 10) << "half the rows cost a few bits each";
  EXPECT_GT(deflate_whole(input).size(), input.size() * 9 / 10) << "noise without copies stays noise";
  for (const std::size_t row :
       {std::size_t{1}, std::size_t{4}, std::size_t{5}, std::size_t{1537}, std::size_t{32768}, std::size_t{40000}}) {
    SCOPED_TRACE(row);
    RunDeflater deflater(row);
    deflater.add(input);
    EXPECT_EQ(inflate_raw(deflater.finish(true), input.size()), input);
  }
}

TEST(RunDeflate, NoiseGrowsByNoMoreThanItsCodes) {
  std::mt19937 random(11);
  Bytes noise(100000);
  for (std::uint8_t& b : noise) b = static_cast<std::uint8_t>(random());
  const Bytes stream = deflate_whole(noise);
  EXPECT_LT(stream.size(), noise.size() + noise.size() / 100 + 200);
  EXPECT_EQ(inflate_raw(stream, noise.size()), noise);
}

TEST(RunDeflate, SkewedCountsKeepCodesWithinFifteenBits) {
  // Symbol k appears fib(k) times: the optimal code for these counts is 24
  // bits deep, which deflate cannot send, so the limit must step in.
  Bytes input;
  std::uint32_t a = 1, b = 1;
  for (int symbol = 0; symbol < 25; ++symbol) {
    input.insert(input.end(), a, static_cast<std::uint8_t>(symbol * 7 + 1));
    const std::uint32_t next = a + b;
    a = b;
    b = next;
  }
  // Shuffled, so that the counts stay literals and not runs.
  std::shuffle(input.begin(), input.end(), std::mt19937(5));
  EXPECT_EQ(inflate_raw(deflate_whole(input), input.size()), input);
}

TEST(RunDeflate, StripsEndOnAByteAndJoin) {
  const Bytes first = {1, 2, 3, 0, 0, 0, 0, 0, 0};
  const Bytes second = {0, 0, 0, 0, 5, 5, 5, 5, 5, 5};
  RunDeflater top;
  top.add(first);
  Bytes stream = top.finish(false);
  // The empty stored block that ends every strip but the last.
  ASSERT_GE(stream.size(), 4u);
  EXPECT_EQ(Bytes(stream.end() - 4, stream.end()), (Bytes{0x00, 0x00, 0xff, 0xff}));
  RunDeflater bottom;
  bottom.add(second);
  const Bytes tail = bottom.finish(true);
  stream.insert(stream.end(), tail.begin(), tail.end());
  Bytes both = first;
  both.insert(both.end(), second.begin(), second.end());
  EXPECT_EQ(inflate_raw(stream, both.size()), both);
}

TEST(RunDeflate, AnEmptyStripIsAValidBlock) {
  RunDeflater empty;
  EXPECT_TRUE(inflate_raw(empty.finish(true), 0).empty());
  RunDeflater none;
  RunDeflater last;
  Bytes stream = none.finish(false);
  const Bytes end = last.finish(true);
  stream.insert(stream.end(), end.begin(), end.end());
  EXPECT_TRUE(inflate_raw(stream, 0).empty());
}

}  // namespace
}  // namespace toond::image
