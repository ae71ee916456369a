// PNG encode time on real toon frames (docs/performance.md).
//   toond_png_bench [--repeats N] [--save DIR] [--level L] [--threads T] [--libdeflate] [FRAME.png ...]
// Without frame files it starts the toond built here, uploads models from
// ../shared/models and renders them with default parameters: the bunny at
// 512² and 1024² (the frames the encode budget is set for) and a spread of
// models and angles at 512², to count how many default frames fit a palette.
// Each frame is then encoded in this process, and the median encode time
// (wall clock, and CPU time over all threads), the PNG size and the colour
// type written are printed, one line a frame. With --libdeflate each frame's
// filtered scanlines are also compressed whole on one thread by zlib and by
// libdeflate at the same level (deflate_compare.h).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench_http.h"
#include "deflate_compare.h"
#include "image/png_codec.h"
#include "stats.h"
#include "support/daemon.h"

namespace {

using toond::image::Image;
using Clock = std::chrono::steady_clock;

struct Frame {
  std::string name;
  Image image;
};

struct Options {
  int repeats = 200;
  int level = toond::image::PngOptions{}.compression_level;
  int threads = toond::image::PngOptions{}.threads;
  std::filesystem::path save_dir;
  std::vector<std::filesystem::path> inputs;
  bool libdeflate = false;
};

Options parse_options(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--repeats" && has_value) {
      options.repeats = std::stoi(argv[++i]);
    } else if (arg == "--level" && has_value) {
      options.level = std::stoi(argv[++i]);
    } else if (arg == "--threads" && has_value) {
      options.threads = std::stoi(argv[++i]);
    } else if (arg == "--libdeflate") {
      options.libdeflate = true;
    } else if (arg == "--save" && has_value) {
      options.save_dir = argv[++i];
    } else if (!arg.empty() && arg[0] != '-') {
      options.inputs.emplace_back(arg);
    } else {
      throw std::runtime_error(
          "usage: toond_png_bench [--repeats N] [--save DIR] [--level L] [--threads T] [--libdeflate] "
          "[FRAME.png ...]");
    }
  }
  return options;
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<Frame> frames_from_files(const std::vector<std::filesystem::path>& paths) {
  std::vector<Frame> frames;
  for (const auto& path : paths) frames.push_back({path.stem().string(), toond::image::decode_png(read_file(path))});
  return frames;
}

// Default parameters but for the model, the size and the camera's yaw.
std::vector<Frame> render_frames(const std::filesystem::path& models) {
  toond::test::Daemon daemon;
  httplib::Client client = daemon.client();
  client.set_read_timeout(120);
  std::vector<Frame> frames;
  auto render = [&](const std::string& name, const std::string& model_id, int size, int yaw) {
    nlohmann::json params = {{"width", size}, {"height", size}, {"camera", {{"yaw", yaw}}}};
    if (!model_id.empty()) params["model"] = model_id;
    const auto answer = toond::bench::render_timed(client, params);
    frames.push_back(
        {name + "-" + std::to_string(size) + "-yaw" + std::to_string(yaw), toond::image::decode_png(answer.png)});
  };
  const std::string bunny = toond::bench::upload_folder(client, models / "stanford-bunny");
  render("bunny", bunny, 512, 0);
  render("bunny", bunny, 1024, 0);
  for (const char* folder : {"stanford-bunny", "spot", "utah-teapot", "armadillo", "bob", "kenney-space-craft"}) {
    const std::string id = toond::bench::upload_folder(client, models / folder);
    for (int yaw : {45, 135, 225, 315}) render(folder, id, 512, yaw);
  }
  for (int yaw : {0, 90, 180, 270}) render("demo", "", 512, yaw);
  return frames;
}

// CPU time of every thread of this process: the work an encode costs,
// whatever else the machine is running meanwhile.
double process_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) / 1e6;
}

int distinct_colours(const Image& image) {
  std::set<std::uint32_t> seen;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    seen.insert(static_cast<std::uint32_t>(image.rgba[i]) | image.rgba[i + 1] << 8 | image.rgba[i + 2] << 16 |
                static_cast<std::uint32_t>(image.rgba[i + 3]) << 24);
  }
  return static_cast<int>(seen.size());
}

const char* colour_type_name(unsigned char type) {
  switch (type) {
    case 0:
      return "grey";
    case 2:
      return "rgb";
    case 3:
      return "palette";
    case 4:
      return "grey+alpha";
    case 6:
      return "rgba";
    default:
      return "?";
  }
}

void bench_frame(const Frame& frame, const Options& options) {
  const toond::image::PngOptions png_options{options.level, options.threads};
  std::string png = toond::image::encode_png(frame.image, png_options);
  if (toond::image::decode_png(png).rgba != frame.image.rgba) {
    throw std::runtime_error(frame.name + ": the PNG does not decode to the frame");
  }
  std::vector<double> ms;
  ms.reserve(static_cast<std::size_t>(options.repeats));
  // Other threads' CPU time is brought up to date only now and then, so it
  // is averaged over every encode rather than taken one encode at a time.
  const double cpu_start = process_cpu_ms();
  for (int i = 0; i < options.repeats; ++i) {
    const auto start = Clock::now();
    png = toond::image::encode_png(frame.image, png_options);
    ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
  }
  const double cpu_ms = (process_cpu_ms() - cpu_start) / std::max(options.repeats, 1);
  const int colours = distinct_colours(frame.image);
  std::printf("%-30s %4dx%-4d colours %6d%s  median %6.3f ms  p90 %6.3f ms  cpu/encode %6.3f ms  %8zu bytes  %s\n",
              frame.name.c_str(), frame.image.width, frame.image.height, colours,
              colours <= 256 ? " (fits)" : "       ", toond::bench::median(ms), toond::bench::percentile(ms, 0.9),
              cpu_ms, png.size(), colour_type_name(static_cast<unsigned char>(png.at(25))));
  if (!options.save_dir.empty()) {
    std::ofstream(options.save_dir / (frame.name + ".png"), std::ios::binary) << png;
  }
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options options = parse_options(argc, argv);
    if (!options.save_dir.empty()) std::filesystem::create_directories(options.save_dir);
    const std::vector<Frame> frames =
        options.inputs.empty() ? render_frames(TOOND_SHARED_MODELS) : frames_from_files(options.inputs);
    int fitting = 0;
    for (const Frame& frame : frames) {
      bench_frame(frame, options);
      if (options.libdeflate) {
        toond::bench::compare_deflaters(frame.name.c_str(), frame.image, options.level, options.repeats);
      }
      fitting += distinct_colours(frame.image) <= 256;
    }
    std::printf("%d of %zu frames have at most 256 colours\n", fitting, frames.size());
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "toond_png_bench: " << e.what() << "\n";
    return 1;
  }
}
