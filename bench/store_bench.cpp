// The model store as it grows (issue 55): for a store of N small models
// (~2 KB of OBJ each, N = 1,000, 10,000 and 100,000 by default), the time
// to open it when its index is missing (a walk of every model) and when it
// is intact, what a render's hold on a model costs (pin and lease, then let
// go: what every render request does to the store), and what an upload
// costs into it unbounded and bounded at its size (each upload then lets
// one model go). The models are written straight into the store's layout
// (no import, no fsync) to fill it quickly; the uploads go through
// ModelStore::put, import and fsyncs included. Medians and 90th percentiles.
//
// --criterion instead measures the issue's: 3,000 distinct ~2 KB uploads
// into an empty store, unbounded and under a 2 MiB bound; the median of the
// last 300 of each, and their ratio.
//   toond_store_bench [--dir DIR] [--models 1000,10000,100000] [--uploads 300] [--leases 2000]
//   toond_store_bench --criterion [--dir DIR]
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "scene/store/model_pins.h"
#include "scene/store/model_store.h"
#include "support/store_fixtures.h"

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using toond::scene::ModelStore;
using toond::scene::StoreOptions;

constexpr std::size_t kModelBytes = 2000;

struct Options {
  fs::path dir = fs::temp_directory_path();
  std::vector<std::size_t> models{1000, 10000, 100000};
  int uploads = 300;
  int leases = 2000;
  bool criterion = false;
};

double since_ms(Clock::time_point started) {
  return std::chrono::duration<double, std::milli>(Clock::now() - started).count();
}

// The value below which `share` of the samples lie.
double quantile(std::vector<double> samples, double share) {
  std::sort(samples.begin(), samples.end());
  return samples[static_cast<std::size_t>(share * static_cast<double>(samples.size() - 1))];
}

struct Costs {
  std::vector<double> ms;
  std::string summary() const {
    char text[64];
    std::snprintf(text, sizeof text, "%.3f (%.3f)", quantile(ms, 0.5), quantile(ms, 0.9));
    return text;
  }
};

Costs uploads(ModelStore& store, const std::string& tag, int count) {
  Costs costs;
  for (int i = 0; i < count; ++i) {
    const toond::scene::Bundle bundle = toond::test::padded_model(tag + "-" + std::to_string(i), kModelBytes);
    const auto started = Clock::now();
    store.put(bundle);
    costs.ms.push_back(since_ms(started));
  }
  return costs;
}

// What a render request does to the store: pins the model when it looks it
// up, leases it when its render is queued, and lets go when answered.
Costs holds(ModelStore& store, std::size_t n, int count) {
  std::mt19937 random(55);
  Costs costs;
  for (int i = 0; i < count; ++i) {
    const std::string id =
        toond::test::stored_id(toond::test::padded_model("stored-" + std::to_string(random() % n), kModelBytes));
    const auto started = Clock::now();
    {
      toond::scene::ModelPins pins(store);
      pins.add(id);
      pins.lease();
    }
    costs.ms.push_back(since_ms(started) * 1000);  // µs
  }
  return costs;
}

void measure(const Options& options, std::size_t n) {
  const fs::path data = options.dir / ("toond-store-bench-" + std::to_string(::getpid()) + "-" + std::to_string(n));
  fs::remove_all(data);
  toond::test::fill_store(data, n, kModelBytes);

  StoreOptions quiet;
  quiet.log = [](const std::string&) {};
  auto started = Clock::now();
  { ModelStore walked(data, quiet); }
  const double walk_s = since_ms(started) / 1000;
  {
    started = Clock::now();
    ModelStore store(data, quiet);
    const double open_s = since_ms(started) / 1000;
    const Costs held = holds(store, n, options.leases);
    const Costs unbounded = uploads(store, "unbounded", options.uploads);
    StoreOptions bound = quiet;
    bound.max_bytes = store.usage().bytes;
    ModelStore bounded_store(data, bound);
    const Costs bounded = uploads(bounded_store, "bounded", options.uploads);
    std::printf("%8zu | %8.2f | %9.3f | %14s | %18s | %18s | %9llu\n", n, walk_s, open_s, held.summary().c_str(),
                unbounded.summary().c_str(), bounded.summary().c_str(),
                static_cast<unsigned long long>(bounded_store.evictions()));
    std::fflush(stdout);
  }  // the stores (and their sweepers, deleting what was let go) first
  fs::remove_all(data);
}

// Both stores take the uploads in turn, so that a busy moment of the
// machine (or of its disk) falls on both alike.
void criterion(const Options& options) {
  const fs::path data = options.dir / ("toond-store-criterion-" + std::to_string(::getpid()));
  fs::remove_all(data);
  StoreOptions unbounded_options;
  StoreOptions bounded_options;
  bounded_options.max_bytes = std::uint64_t{2} << 20;
  auto unbounded = std::make_unique<ModelStore>(data / "unbounded", unbounded_options);
  auto bounded = std::make_unique<ModelStore>(data / "bounded", bounded_options);
  Costs costs[2];
  for (int i = 0; i < 3000; ++i) {
    const toond::scene::Bundle bundle = toond::test::padded_model("criterion-" + std::to_string(i), kModelBytes);
    ModelStore* stores[2] = {unbounded.get(), bounded.get()};
    for (int k = 0; k < 2; ++k) {
      const auto started = Clock::now();
      stores[k]->put(bundle);
      costs[k].ms.push_back(since_ms(started));
    }
  }
  double medians[2];
  for (int k = 0; k < 2; ++k) {
    const std::vector<double> last(costs[k].ms.end() - 300, costs[k].ms.end());
    medians[k] = quantile(last, 0.5);
    std::printf("%-18s median %.3f ms, p90 %.3f ms of the last 300 of 3,000 uploads; %zu models kept\n",
                k ? "--max-store-mb 2:" : "unbounded:", medians[k], quantile(last, 0.9),
                (k ? bounded : unbounded)->usage().models);
  }
  std::printf("bounded / unbounded: %.2f\n", medians[1] / medians[0]);
  unbounded.reset();
  bounded.reset();
  fs::remove_all(data);
}

std::vector<std::size_t> counts(const std::string& list) {
  std::vector<std::size_t> values;
  std::stringstream ss(list);
  for (std::string item; std::getline(ss, item, ',');) values.push_back(std::stoul(item));
  return values;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--criterion") {
      options.criterion = true;
    } else if (arg == "--dir" && has_value) {
      options.dir = argv[++i];
    } else if (arg == "--models" && has_value) {
      options.models = counts(argv[++i]);
    } else if (arg == "--uploads" && has_value) {
      options.uploads = std::atoi(argv[++i]);
    } else if (arg == "--leases" && has_value) {
      options.leases = std::atoi(argv[++i]);
    } else {
      std::fprintf(stderr,
                   "usage: toond_store_bench [--dir DIR] [--models N,N,…] [--uploads N] [--leases N]\n"
                   "       toond_store_bench --criterion [--dir DIR]\n");
      return 2;
    }
  }
  if (options.criterion) {
    criterion(options);
    return 0;
  }
  std::printf(
      "  models | start s  | start s   | render hold    | upload ms          | upload ms          | let go\n"
      "         | (walk)   | (index)   | µs (p90)       | unbounded (p90)    | bounded (p90)      |\n");
  for (const std::size_t n : options.models) measure(options, n);
  return 0;
}
