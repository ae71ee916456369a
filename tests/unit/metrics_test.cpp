#include <gtest/gtest.h>

#include <limits>

#include "http/metrics.h"
#include "http/service_metrics.h"

namespace toond::http {
namespace {

TEST(Metrics, CountersWriteOneLinePerLabelSetWithHelpAndType) {
  MetricsRegistry registry;
  CounterFamily& requests = registry.counter("x_requests_total", "Requests.", {"route", "status"});
  requests.add({"/render", "200"});
  requests.add({"/render", "200"});
  requests.add({"/models", "404"}, 3);
  EXPECT_EQ(requests.value({"/render", "200"}), 2);
  EXPECT_EQ(registry.exposition(),
            "# HELP x_requests_total Requests.\n"
            "# TYPE x_requests_total counter\n"
            "x_requests_total{route=\"/models\",status=\"404\"} 3\n"
            "x_requests_total{route=\"/render\",status=\"200\"} 2\n");
}

TEST(Metrics, AnUnlabelledCounterReportsZeroBeforeItsFirstEvent) {
  MetricsRegistry registry;
  registry.counter("x_hits_total", "Hits.");
  EXPECT_NE(registry.exposition().find("\nx_hits_total 0\n"), std::string::npos) << registry.exposition();
}

// Prometheus' convention: every series a family will have is there from the
// first scrape. An unlabelled histogram has one, all zero.
TEST(Metrics, AnUnlabelledHistogramReportsZerosBeforeItsFirstEvent) {
  MetricsRegistry registry;
  registry.histogram("x_seconds", "Time.", {}, {0.1, 1});
  EXPECT_EQ(registry.exposition(),
            "# HELP x_seconds Time.\n"
            "# TYPE x_seconds histogram\n"
            "x_seconds_bucket{le=\"0.1\"} 0\n"
            "x_seconds_bucket{le=\"1\"} 0\n"
            "x_seconds_bucket{le=\"+Inf\"} 0\n"
            "x_seconds_sum 0\n"
            "x_seconds_count 0\n");
}

TEST(Metrics, LabelValuesAreEscaped) {
  EXPECT_EQ(format_labels({"a"}, {"q\"b\\s\nn"}), "{a=\"q\\\"b\\\\s\\nn\"}");
  EXPECT_EQ(format_labels({}, {}), "");
}

TEST(Metrics, ValuesUseTheFormatsSpellings) {
  EXPECT_EQ(format_value(0.25), "0.25");
  EXPECT_EQ(format_value(3), "3");
  EXPECT_EQ(format_value(std::numeric_limits<double>::infinity()), "+Inf");
  EXPECT_EQ(format_value(std::numeric_limits<double>::quiet_NaN()), "NaN");
}

TEST(Metrics, HistogramBucketsAreCumulativeAndEndWithInf) {
  MetricsRegistry registry;
  HistogramFamily& h = registry.histogram("x_seconds", "Time.", {"pass"}, {0.1, 1});
  h.observe({"draw"}, 0.0625);
  h.observe({"draw"}, 0.5);
  h.observe({"draw"}, 0.5);
  h.observe({"draw"}, 7);
  EXPECT_EQ(registry.exposition(),
            "# HELP x_seconds Time.\n"
            "# TYPE x_seconds histogram\n"
            "x_seconds_bucket{pass=\"draw\",le=\"0.1\"} 1\n"
            "x_seconds_bucket{pass=\"draw\",le=\"1\"} 3\n"
            "x_seconds_bucket{pass=\"draw\",le=\"+Inf\"} 4\n"
            "x_seconds_sum{pass=\"draw\"} 8.0625\n"
            "x_seconds_count{pass=\"draw\"} 4\n");
}

TEST(Metrics, GaugesAreReadAtEveryScrape) {
  MetricsRegistry registry;
  int depth = 2;
  registry.gauge("x_depth", "Depth.", [&depth] { return depth; });
  EXPECT_NE(registry.exposition().find("x_depth 2\n"), std::string::npos);
  depth = 5;
  EXPECT_NE(registry.exposition().find("x_depth 5\n"), std::string::npos);
}

TEST(Metrics, AWrongLabelCountIsRefused) {
  MetricsRegistry registry;
  CounterFamily& c = registry.counter("x_total", "X.", {"a"});
  EXPECT_THROW(c.add({"1", "2"}), std::logic_error);
}

TEST(Metrics, RoutesAreLabelledByTemplateNotByPath) {
  const std::string id = "0123456789abcdef0123456789abcdef";
  EXPECT_EQ(route_label("/render"), "/render");
  EXPECT_EQ(route_label("/models"), "/models");
  EXPECT_EQ(route_label("/models/" + id), "/models/{id}");
  EXPECT_EQ(route_label("/models/" + id + "/render"), "/models/{id}/render");
  EXPECT_EQ(route_label("/models/" + id + "/other"), "other");
  EXPECT_EQ(route_label("/no/such/route"), "other");
  EXPECT_EQ(route_label("/app.js"), "/{file}");
  EXPECT_EQ(route_label("/lib/controls.css"), "/{file}");
  EXPECT_EQ(route_label("/../etc/passwd"), "other");
}

TEST(Metrics, CountersKeptElsewhereAreReadAtScrapeAndTypedAsCounters) {
  MetricsRegistry registry;
  std::size_t hits = 7;
  registry.counter_from("x_hits_total", "Hits.", [&hits] { return static_cast<double>(hits); });
  EXPECT_EQ(registry.exposition(), "# HELP x_hits_total Hits.\n# TYPE x_hits_total counter\nx_hits_total 7\n");
}

render::PassTiming timing(const std::string& pass, double ms) {
  render::PassTiming t;
  t.pass = pass;
  t.ms = ms;
  return t;
}

TEST(Metrics, ServiceMetricsTimeRendersAndEachStage) {
  ServiceMetrics metrics;
  metrics.observe_render(0.02, {timing("shade", 4.0), timing("outline", 1.0)}, 1.5, 2.0, "png");
  const std::string text = metrics.registry().exposition();
  EXPECT_NE(text.find("toond_render_seconds_count 1\n"), std::string::npos) << text;
  EXPECT_NE(text.find("toond_render_seconds_bucket{le=\"0.025\"} 1\n"), std::string::npos) << text;
  EXPECT_NE(text.find("toond_render_seconds_bucket{le=\"0.01\"} 0\n"), std::string::npos) << text;
  EXPECT_NE(text.find("toond_render_pass_seconds_sum{pass=\"shade\"} 0.004\n"), std::string::npos) << text;
  EXPECT_NE(text.find("toond_render_pass_seconds_count{pass=\"outline\"} 1\n"), std::string::npos) << text;
  EXPECT_NE(text.find("toond_render_pass_seconds_sum{pass=\"queue\"} 0.0015\n"), std::string::npos) << text;
  EXPECT_NE(text.find("toond_render_pass_seconds_sum{pass=\"png\"} 0.002\n"), std::string::npos) << text;
}

}  // namespace
}  // namespace toond::http
