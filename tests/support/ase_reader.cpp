#include "support/ase_reader.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <algorithm>

namespace toond::test {
namespace {

struct Reader {
  const std::string& b;
  std::size_t at = 0;
  unsigned u8() { return static_cast<std::uint8_t>(b.at(at++)); }
  unsigned u16() { return u8() | (u8() << 8); }
  std::uint32_t u32() { return u16() | (static_cast<std::uint32_t>(u16()) << 16); }
  int i16() { return static_cast<std::int16_t>(u16()); }
  int i32() { return static_cast<std::int32_t>(u32()); }
  std::string str() {
    const unsigned n = u16();
    at += n;
    return b.substr(at - n, n);
  }
};

void read_chunk(Reader& r, int type, std::size_t end, int frame, AseRead& ase) {
  if (type == 0x2018) {
    const unsigned n = r.u16();
    r.at += 8;
    for (unsigned i = 0; i < n; ++i) {
      AseRead::Tag t{};
      t.from = static_cast<int>(r.u16());
      t.to = static_cast<int>(r.u16());
      t.direction = static_cast<int>(r.u8());
      t.repeat = static_cast<int>(r.u16());
      r.at += 6 + 4;
      t.name = r.str();
      ase.tags.push_back(t);
    }
  } else if (type == 0x2004) {
    r.at += 16;
    ase.layers.push_back(r.str());
  } else if (type == 0x2005) {
    AseRead::Cel c{};
    c.frame = frame;
    c.layer = static_cast<int>(r.u16());
    c.x = r.i16();
    c.y = r.i16();
    r.at += 1;
    EXPECT_EQ(r.u16(), 2u) << "compressed image cels";
    r.at += 7;
    c.w = static_cast<int>(r.u16());
    c.h = static_cast<int>(r.u16());
    c.rgba.resize(static_cast<std::size_t>(c.w) * c.h * 4);
    uLongf size = c.rgba.size();
    EXPECT_EQ(uncompress(c.rgba.data(), &size, reinterpret_cast<const Bytef*>(r.b.data() + r.at), end - r.at), Z_OK);
    EXPECT_EQ(size, c.rgba.size());
    ase.cels.push_back(std::move(c));
  } else if (type == 0x2022) {
    const std::uint32_t keys = r.u32();
    EXPECT_EQ(r.u32(), 2u) << "a slice with a pivot";
    r.at += 4;
    EXPECT_EQ(r.str(), "pivot");
    for (std::uint32_t k = 0; k < keys; ++k) {
      const int f = static_cast<int>(r.u32());
      r.at += 16;
      const int x = r.i32();
      ase.pivot_keys.push_back({f, x, r.i32()});
    }
  }
}

}  // namespace

AseRead read_aseprite(const std::string& bytes) {
  AseRead ase;
  Reader r{bytes};
  ase.file_size = r.u32();
  EXPECT_EQ(r.u16(), 0xA5E0u);
  ase.frames = static_cast<int>(r.u16());
  ase.width = static_cast<int>(r.u16());
  ase.height = static_cast<int>(r.u16());
  ase.depth = static_cast<int>(r.u16());
  r.at = 26;
  ase.colours = static_cast<int>(r.u16());
  r.at = 128;
  for (int f = 0; f < ase.frames; ++f) {
    const std::size_t start = r.at;
    const std::uint32_t size = r.u32();
    EXPECT_EQ(r.u16(), 0xF1FAu);
    const unsigned old_chunks = r.u16();
    ase.durations.push_back(static_cast<int>(r.u16()));
    r.at += 2;
    const std::uint32_t chunks = r.u32();
    EXPECT_EQ(old_chunks, chunks);
    ase.chunk_types.emplace_back();
    for (std::uint32_t c = 0; c < chunks; ++c) {
      const std::size_t chunk_start = r.at;
      const std::uint32_t chunk_size = r.u32();
      const int type = static_cast<int>(r.u16());
      ase.chunk_types.back().push_back(type);
      read_chunk(r, type, chunk_start + chunk_size, f, ase);
      r.at = chunk_start + chunk_size;
    }
    EXPECT_EQ(r.at, start + size) << "frame " << f << "'s size";
  }
  EXPECT_EQ(r.at, bytes.size());
  return ase;
}

std::vector<std::uint8_t> cel_on_canvas(const AseRead::Cel& cel, int width, int height) {
  std::vector<std::uint8_t> canvas(static_cast<std::size_t>(width) * height * 4, 0);
  for (int y = 0; y < cel.h; ++y) {
    const std::size_t to = (static_cast<std::size_t>(cel.y + y) * width + cel.x) * 4;
    std::copy_n(cel.rgba.begin() + static_cast<long>(y) * cel.w * 4, cel.w * 4, canvas.begin() + static_cast<long>(to));
  }
  return canvas;
}

std::vector<std::uint8_t> visible_pixels(std::vector<std::uint8_t> rgba) {
  for (std::size_t i = 0; i + 3 < rgba.size(); i += 4) {
    if (rgba[i + 3] == 0) std::fill_n(rgba.begin() + static_cast<long>(i), 4, 0);
  }
  return rgba;
}

}  // namespace toond::test
