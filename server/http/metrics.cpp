#include "http/metrics.h"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace toond::http {
namespace {

void write_header(std::string& out, const std::string& name, const std::string& help, const char* type) {
  out += "# HELP " + name + " " + help + "\n";
  out += "# TYPE " + name + " " + type + "\n";
}

void check_arity(const std::string& name, const std::vector<std::string>& names, const LabelValues& values) {
  // A wrong label count is a programming error; failing loudly keeps the
  // exposition well-formed.
  if (names.size() != values.size()) throw std::logic_error("metric " + name + ": wrong number of labels");
}

}  // namespace

std::string format_labels(const std::vector<std::string>& names, const LabelValues& values) {
  if (names.empty()) return "";
  std::string out = "{";
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i) out += ',';
    out += names[i] + "=\"";
    for (char c : values[i]) {
      if (c == '\\')
        out += "\\\\";
      else if (c == '"')
        out += "\\\"";
      else if (c == '\n')
        out += "\\n";
      else
        out += c;
    }
    out += '"';
  }
  return out + "}";
}

std::string format_value(double value) {
  if (std::isnan(value)) return "NaN";
  if (std::isinf(value)) return value > 0 ? "+Inf" : "-Inf";
  char buf[64];
  const auto result = std::to_chars(buf, buf + sizeof buf, value);
  return std::string(buf, result.ptr);
}

CounterFamily::CounterFamily(std::string name, std::string help, std::vector<std::string> label_names)
    : name_(std::move(name)), help_(std::move(help)), label_names_(std::move(label_names)) {}

void CounterFamily::add(const LabelValues& labels, double amount) {
  check_arity(name_, label_names_, labels);
  std::lock_guard lock(mutex_);
  values_[labels] += amount;
}

double CounterFamily::value(const LabelValues& labels) const {
  std::lock_guard lock(mutex_);
  const auto it = values_.find(labels);
  return it == values_.end() ? 0.0 : it->second;
}

void CounterFamily::write(std::string& out) const {
  write_header(out, name_, help_, "counter");
  std::lock_guard lock(mutex_);
  // A family without labels reports 0 before its first event, so a scraper
  // sees the series from the start.
  if (values_.empty() && label_names_.empty()) out += name_ + " 0\n";
  for (const auto& [labels, value] : values_) {
    out += name_ + format_labels(label_names_, labels) + " " + format_value(value) + "\n";
  }
}

HistogramFamily::HistogramFamily(std::string name, std::string help, std::vector<std::string> label_names,
                                 std::vector<double> bounds)
    : name_(std::move(name)), help_(std::move(help)), label_names_(std::move(label_names)), bounds_(std::move(bounds)) {
  // A family without labels has its one series, all zero, from the start:
  // a scraper sees it before the first event, as it sees an unlabelled
  // counter, and rates and alerts on it need no special case for "absent".
  if (label_names_.empty()) series_[{}].buckets.assign(bounds_.size(), 0);
}

void HistogramFamily::observe(const LabelValues& labels, double value) {
  check_arity(name_, label_names_, labels);
  std::lock_guard lock(mutex_);
  Series& s = series_[labels];
  if (s.buckets.empty()) s.buckets.assign(bounds_.size(), 0);
  for (std::size_t i = 0; i < bounds_.size(); ++i) {
    if (value <= bounds_[i]) {
      ++s.buckets[i];
      break;
    }
  }
  ++s.count;
  s.sum += value;
}

void HistogramFamily::write(std::string& out) const {
  write_header(out, name_, help_, "histogram");
  std::vector<std::string> bucket_names = label_names_;
  bucket_names.push_back("le");
  std::lock_guard lock(mutex_);
  for (const auto& [labels, s] : series_) {
    LabelValues bucket_labels = labels;
    bucket_labels.emplace_back();
    std::uint64_t cumulative = 0;
    for (std::size_t i = 0; i < bounds_.size(); ++i) {
      cumulative += s.buckets[i];
      bucket_labels.back() = format_value(bounds_[i]);
      out += name_ + "_bucket" + format_labels(bucket_names, bucket_labels) + " " + std::to_string(cumulative) + "\n";
    }
    bucket_labels.back() = "+Inf";
    out += name_ + "_bucket" + format_labels(bucket_names, bucket_labels) + " " + std::to_string(s.count) + "\n";
    const std::string plain = format_labels(label_names_, labels);
    out += name_ + "_sum" + plain + " " + format_value(s.sum) + "\n";
    out += name_ + "_count" + plain + " " + std::to_string(s.count) + "\n";
  }
}

CounterFamily& MetricsRegistry::counter(std::string name, std::string help, std::vector<std::string> label_names) {
  std::lock_guard lock(mutex_);
  counters_.emplace_back(std::move(name), std::move(help), std::move(label_names));
  order_.emplace_back(0, counters_.size() - 1);
  return counters_.back();
}

HistogramFamily& MetricsRegistry::histogram(std::string name, std::string help, std::vector<std::string> label_names,
                                            std::vector<double> bounds) {
  std::lock_guard lock(mutex_);
  histograms_.emplace_back(std::move(name), std::move(help), std::move(label_names), std::move(bounds));
  order_.emplace_back(1, histograms_.size() - 1);
  return histograms_.back();
}

void MetricsRegistry::gauge(std::string name, std::string help, std::function<double()> read) {
  std::lock_guard lock(mutex_);
  gauges_.push_back({std::move(name), std::move(help), std::move(read), "gauge"});
  order_.emplace_back(2, gauges_.size() - 1);
}

void MetricsRegistry::counter_from(std::string name, std::string help, std::function<double()> read) {
  std::lock_guard lock(mutex_);
  gauges_.push_back({std::move(name), std::move(help), std::move(read), "counter"});
  order_.emplace_back(2, gauges_.size() - 1);
}

std::string MetricsRegistry::exposition() const {
  std::lock_guard lock(mutex_);
  std::string out;
  for (const auto& [kind, index] : order_) {
    if (kind == 0) {
      counters_[index].write(out);
    } else if (kind == 1) {
      histograms_[index].write(out);
    } else {
      const Gauge& g = gauges_[index];
      write_header(out, g.name, g.help, g.type);
      out += g.name + " " + format_value(g.read()) + "\n";
    }
  }
  return out;
}

}  // namespace toond::http
