// What an upload costs the model store as it grows (issue 55): with its
// index, the number of models kept does not show in the time of an upload,
// bounded (each upload then lets one go) or not; an upload's own cost (an
// import, the fsyncs of its files) is the same at any size. Timed, so it
// lives with the other scaling tests, which run one at a time and only in
// the plain build. The issue's own measure (3,000 uploads through the
// daemon, bounded against unbounded) is bench/store_uploads.py's.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "scene/store/model_store.h"
#include "support/store_fixtures.h"

namespace toond::scene {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t kModelBytes = 2000;

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

// Stores of n and 4n models take uploads in turn (so that a busy moment of
// the machine falls on both alike), first unbounded, then each bounded at
// what it then holds, so that every upload lets models go. Before the index, an upload under the bound walked the
// store: 6.5 ms at ~450 models kept, 20.5 ms at ~870, against 1.8 ms
// unbounded. The stores are small because deleting them afterwards is what
// takes longest on some disks (a few ms a folder where blocks are
// discarded as they are freed).
TEST(StoreScaling, AnUploadCostsTheSameWithFourTimesTheModels) {
  const fs::path dir = fs::temp_directory_path() / ("toond-store-scaling-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  constexpr std::size_t n = 150;
  constexpr int kUploads = 41;
  const std::size_t sizes[2] = {n, 4 * n};
  StoreOptions options;
  options.log = [](const std::string&) {};
  std::unique_ptr<ModelStore> stores[2];
  for (int k = 0; k < 2; ++k) {
    test::fill_store(dir / std::to_string(sizes[k]), sizes[k], kModelBytes, false);
    stores[k] = std::make_unique<ModelStore>(dir / std::to_string(sizes[k]), options);
  }
  double medians[2][2];  // [bounded][size]
  for (int bounded = 0; bounded < 2; ++bounded) {
    if (bounded) {
      for (int k = 0; k < 2; ++k) {
        StoreOptions at_its_size = options;
        at_its_size.max_bytes = stores[k]->usage().bytes;
        stores[k].reset();
        stores[k] = std::make_unique<ModelStore>(dir / std::to_string(sizes[k]), at_its_size);
      }
    }
    std::vector<double> ms[2];
    for (int i = 0; i < kUploads; ++i) {
      for (int k = 0; k < 2; ++k) {
        const Bundle bundle = test::padded_model(std::to_string(bounded) + "-" + std::to_string(i), kModelBytes);
        const auto started = std::chrono::steady_clock::now();
        stores[k]->put(bundle);
        ms[k].push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count());
      }
    }
    for (int k = 0; k < 2; ++k) {
      medians[bounded][k] = median(ms[k]);
      std::printf("[store] %zu models, %s: median upload %.3f ms\n", sizes[k], bounded ? "bounded" : "unbounded",
                  medians[bounded][k]);
    }
  }
  for (int k = 0; k < 2; ++k) {
    // The filled models are their info.json alone, smaller than an upload:
    // each bounded upload lets a few go.
    EXPECT_GE(stores[k]->evictions(), static_cast<std::uint64_t>(kUploads)) << "a bounded upload let none go";
    stores[k].reset();
  }
  std::printf("[store] bounded / unbounded: %.2f at n, %.2f at 4n\n", medians[1][0] / medians[0][0],
              medians[1][1] / medians[0][1]);
  EXPECT_LT(medians[0][1] / medians[0][0], 1.5) << "unbounded, 4n / n models";
  EXPECT_LT(medians[1][1] / medians[1][0], 1.5) << "bounded, 4n / n models";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace toond::scene
