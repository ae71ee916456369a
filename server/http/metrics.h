#pragma once
// A small metrics registry written out in Prometheus' text exposition format
// (version 0.0.4): counters and histograms with labels, and gauges read when
// scraped. Thread-safe; families live as long as the registry, so the
// references it hands out stay valid.
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace toond::http {

// Label name → value, in the order the family declares its label names.
using LabelValues = std::vector<std::string>;

class CounterFamily {
 public:
  CounterFamily(std::string name, std::string help, std::vector<std::string> label_names);
  void add(const LabelValues& labels, double amount = 1);
  double value(const LabelValues& labels) const;
  void write(std::string& out) const;

 private:
  std::string name_, help_;
  std::vector<std::string> label_names_;
  mutable std::mutex mutex_;
  std::map<LabelValues, double> values_;
};

class HistogramFamily {
 public:
  // `bounds`: the buckets' upper bounds, ascending; +Inf is added.
  HistogramFamily(std::string name, std::string help, std::vector<std::string> label_names, std::vector<double> bounds);
  void observe(const LabelValues& labels, double value);
  void write(std::string& out) const;

 private:
  struct Series {
    std::vector<std::uint64_t> buckets;  // per bound, not cumulative
    std::uint64_t count = 0;
    double sum = 0;
  };
  std::string name_, help_;
  std::vector<std::string> label_names_;
  std::vector<double> bounds_;
  mutable std::mutex mutex_;
  std::map<LabelValues, Series> series_;
};

class MetricsRegistry {
 public:
  CounterFamily& counter(std::string name, std::string help, std::vector<std::string> label_names = {});
  HistogramFamily& histogram(std::string name, std::string help, std::vector<std::string> label_names,
                             std::vector<double> bounds);
  // A gauge whose value is read from `read` at every scrape (queue depth,
  // models loaded), so nothing has to keep it up to date.
  void gauge(std::string name, std::string help, std::function<double()> read);
  // A counter something else keeps (the result cache's hits), read at every
  // scrape like a gauge but typed as a counter.
  void counter_from(std::string name, std::string help, std::function<double()> read);

  // Every family, in registration order.
  std::string exposition() const;

 private:
  struct Gauge {
    std::string name, help;
    std::function<double()> read;
    const char* type;
  };
  mutable std::mutex mutex_;
  std::deque<CounterFamily> counters_;
  std::deque<HistogramFamily> histograms_;
  std::deque<Gauge> gauges_;
  // (kind, index) in registration order: 0 counter, 1 histogram, 2 gauge.
  std::vector<std::pair<int, std::size_t>> order_;
};

// The `{a="x",b="y"}` part of a sample line, with values escaped as the
// format requires; empty when there are no labels.
std::string format_labels(const std::vector<std::string>& names, const LabelValues& values);
// A sample value as the format writes it (+Inf, NaN, shortest round trip).
std::string format_value(double value);

}  // namespace toond::http
