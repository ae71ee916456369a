#pragma once
// An .aseprite file read back as Aseprite's published format lays it out:
// what a reader of the spec finds, chunk by chunk (the header, each
// frame's chunks, tags, layers, compressed image cels, the pivot slice).
// Mismatches with the format are reported as test failures.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace toond::test {

struct AseRead {
  int frames = 0, width = 0, height = 0, depth = 0, colours = 0;
  std::uint32_t file_size = 0;
  std::vector<int> durations;
  std::vector<std::vector<int>> chunk_types;  // per frame
  struct Tag {
    int from, to, direction, repeat;
    std::string name;
  };
  std::vector<Tag> tags;
  std::vector<std::string> layers;
  struct Cel {
    int frame, layer, x, y, w, h;
    std::vector<std::uint8_t> rgba;
  };
  std::vector<Cel> cels;
  std::vector<std::array<int, 3>> pivot_keys;  // frame, x, y
};

AseRead read_aseprite(const std::string& bytes);

// A cel's pixels at their place on a transparent width × height canvas
// (RGBA rows): what its layer shows in its frame.
std::vector<std::uint8_t> cel_on_canvas(const AseRead::Cel& cel, int width, int height);

// `rgba` with every fully transparent pixel made (0, 0, 0, 0): a colour
// that shows nowhere compares as none.
std::vector<std::uint8_t> visible_pixels(std::vector<std::uint8_t> rgba);

}  // namespace toond::test
