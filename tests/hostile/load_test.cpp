// A bounded load test on loopback: 16 clients mix renders (each with its
// own camera yaw, so nearly none is a result-cache hit), uploads and bad
// requests for TOOND_LOAD_SECONDS (default 10) against one daemon with a
// small queue. Every answer must be 2xx, a 4xx the request deserved, or 503
// (queue full, with Retry-After); every PNG must decode at the size asked;
// the daemon's resident memory must not grow after warm-up.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <map>
#include <mutex>
#include <random>
#include <sstream>
#include <thread>

#include "image/png_codec.h"
#include "test_client.h"

namespace toond::test {
namespace {

using Clock = std::chrono::steady_clock;
using nlohmann::json;

// Resident set of a process in KiB, from /proc/PID/status.
long rss_kib(int pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
  }
  return -1;
}

struct Tally {
  std::mutex mutex;
  std::map<std::string, int> counts;  // "render 200", "bad 400", ...
  std::vector<std::string> failures;
  void add(const std::string& kind, int status) {
    std::lock_guard lock(mutex);
    ++counts[kind + " " + std::to_string(status)];
  }
  // Connections closed before any answer (httplib::Error::Read). Seen only
  // with the machine oversubscribed (three of these tests at once beside
  // other builds on 2 cores), most likely httplib's 5 s keep-alive/read
  // timeout closing a connection whose client thread stalled before
  // sending. Counted, printed and bounded; never an HTTP status.
  std::map<std::string, int> drops;
  void dropped(const std::string& kind, httplib::Error error) {
    std::lock_guard lock(mutex);
    ++drops[kind + " " + httplib::to_string(error)];
  }
  void fail(const std::string& what) {
    std::lock_guard lock(mutex);
    if (failures.size() < 20) failures.push_back(what);
  }
};

std::string model_text(unsigned n) {
  std::ostringstream obj;
  obj << "# load " << n << "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 " << 1 + n % 7
      << "\nf 1 2 3\nf 1 2 4\nf 1 3 4\nf 2 3 4\n";
  return obj.str();
}

TEST(Load, SixteenClientsMixedForBoundedTime) {
  const char* seconds_env = std::getenv("TOOND_LOAD_SECONDS");
  const int seconds = seconds_env ? std::atoi(seconds_env) : 10;
  // A 1 MiB result cache fills within the warm-up; the default (larger)
  // one would still be filling with these all-different renders, which is
  // bounded growth, not a leak, but would hide one.
  Daemon daemon({}, {"--queue", "4", "--threads", "16", "--result-cache-mb", "1"});
  auto setup = daemon.client();
  const std::string model = upload_obj_text(setup, model_text(0));
  ASSERT_FALSE(model.empty());

  Tally tally;
  std::atomic<bool> stop{false};
  std::atomic<long> pngs{0};
  std::vector<long> rss_samples;
  const auto start = Clock::now();
  std::vector<std::thread> clients;
  for (int c = 0; c < 16; ++c) {
    clients.emplace_back([&, c] {
      std::mt19937 rng(static_cast<unsigned>(c) * 7919u + 1);
      auto client = daemon.client();
      unsigned n = static_cast<unsigned>(c) * 100000u;
      while (!stop) {
        const int pick = static_cast<int>(rng() % 10);
        if (pick < 5) {
          const int size = 32 + static_cast<int>(rng() % 4) * 32;
          // A random yaw: (nearly) every render is new, so the result
          // cache does not answer it and the render thread is kept busy.
          const double yaw = static_cast<double>(rng() % 36000) / 100.0 - 180.0;
          json params = {{"width", size}, {"height", size}, {"outline", {{"width", 2}}}, {"camera", {{"yaw", yaw}}}};
          if (pick == 1) params["model"] = model;
          auto res = post_json(client, "/render", params);
          if (!res) {
            tally.dropped("render", res.error());
            continue;
          }
          tally.add("render", res->status);
          if (res->status == 200) {
            try {
              const image::Image img = image::decode_png(res->body);
              if (img.width != size || img.height != size) tally.fail("render: PNG of the wrong size");
              ++pngs;
            } catch (const std::exception& e) {
              tally.fail(std::string("render: PNG does not decode: ") + e.what());
            }
          } else if (res->status == 503) {
            if (!res->has_header("Retry-After")) tally.fail("503 without Retry-After");
          } else {
            tally.fail("render answered " + std::to_string(res->status) + ": " + res->body.substr(0, 200));
          }
        } else if (pick < 7) {
          // New bundles (ids differ) and repeats of earlier ones.
          const unsigned id = pick == 5 ? n++ : n % 50;
          httplib::MultipartFormDataItems items = {{"file", model_text(id), "m.obj", ""}};
          auto res = client.Post("/models", items);
          if (!res) {
            tally.dropped("upload", res.error());
            continue;
          }
          tally.add("upload", res->status);
          if (res->status != 200 && res->status != 201) tally.fail("upload answered " + std::to_string(res->status));
        } else {
          // Requests that deserve a 4xx, each of its own kind.
          httplib::Result res = [&]() -> httplib::Result {
            switch (pick) {
              case 7:
                return client.Post("/render", "{\"width\": 12", "application/json");
              case 8:
                return post_json(client, "/render", {{"outline", {{"width", 1000}}}});
              default: {
                httplib::MultipartFormDataItems items = {{"file", "v 0 0 0\n", "../x.obj", ""}};
                return client.Post("/models", items);
              }
            }
          }();
          if (!res) {
            tally.dropped("bad request", res.error());
            continue;
          }
          tally.add("bad", res->status);
          if (res->status != 400) tally.fail("bad request answered " + std::to_string(res->status));
        }
      }
    });
  }
  // RSS once a second; the first third is warm-up (program cache, GPU model
  // cache, allocator pools filling).
  while (Clock::now() - start < std::chrono::seconds(seconds)) {
    std::this_thread::sleep_for(std::chrono::seconds(1));
    rss_samples.push_back(rss_kib(daemon.pid()));
  }
  stop = true;
  for (auto& t : clients) t.join();

  auto health = setup.Get("/healthz");
  ASSERT_TRUE(health);
  EXPECT_EQ(health->status, 200);
  for (const auto& f : tally.failures) ADD_FAILURE() << f;
  std::ostringstream summary;
  for (const auto& [kind, count] : tally.counts) summary << kind << ": " << count << "; ";
  std::cout << "[load] " << seconds << " s, " << pngs << " PNGs; " << summary.str() << "\n[load] RSS KiB:";
  for (const long kib : rss_samples) std::cout << " " << kib;
  std::cout << std::endl;
  EXPECT_GT(pngs.load(), 0);
  int answered = 0;
  int dropped = 0;
  for (const auto& [kind, count] : tally.counts) answered += count;
  for (const auto& [kind, count] : tally.drops) {
    dropped += count;
    std::cout << "[load] no answer: " << kind << " x" << count << "\n";
  }
  // At most one request in a thousand may lose its connection that way.
  EXPECT_LE(dropped * 1000, answered) << dropped << " requests got no answer out of " << answered + dropped;

  ASSERT_GE(rss_samples.size(), 3u);
#if defined(__SANITIZE_ADDRESS__)
  // ASan keeps freed memory in quarantine (up to 256 MiB) and adds shadow
  // memory, so the daemon's resident set says nothing about leaks here; the
  // leak checker does. Everything else above was checked.
  std::cout << "[load] RSS flatness not asserted under AddressSanitizer (quarantine)" << std::endl;
  return;
#endif
  const std::size_t warm = rss_samples.size() / 3;
  const long after_warm_up = rss_samples[warm];
  long highest_later = 0;
  for (std::size_t i = warm; i < rss_samples.size(); ++i) highest_later = std::max(highest_later, rss_samples[i]);
  // Flat: after warm-up the resident set grows by less than a tenth (and
  // 32 MiB, the size of a few render targets and malloc arenas).
  EXPECT_LT(highest_later - after_warm_up, std::max(after_warm_up / 10, 32L * 1024))
      << "RSS after warm-up " << after_warm_up << " KiB, later up to " << highest_later << " KiB";
}

}  // namespace
}  // namespace toond::test
