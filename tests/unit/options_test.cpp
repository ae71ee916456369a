#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <set>
#include <stdexcept>
#include <string>

#include "app/options.h"
#include "help_checks.h"

namespace toond::app {
namespace {

TEST(DaemonOptions, DefaultsFollowTheWireContract) {
  const Options o = parse_options({});
  EXPECT_EQ(o.host, "127.0.0.1");
  EXPECT_EQ(o.port, 8080);
  EXPECT_FALSE(o.gpu.has_value());
}

TEST(DaemonOptions, ListenDataDirAndGpu) {
  const Options o = parse_options({"--listen", "0.0.0.0:0", "--data-dir", "/tmp/x", "--gpu", "1"});
  EXPECT_EQ(o.host, "0.0.0.0");
  EXPECT_EQ(o.port, 0);
  EXPECT_EQ(o.data_dir, "/tmp/x");
  EXPECT_EQ(o.gpu, 1);
}

TEST(DaemonOptions, BadValuesNameTheFlag) {
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"--listen", "8080"}, {"--listen", "host:99999"}, {"--gpu", "x"}, {"--queue"}, {"--frobnicate"}}) {
    try {
      parse_options(args);
      FAIL() << "accepted " << args[0];
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(args[0]), std::string::npos) << e.what();
    }
  }
}

TEST(DaemonOptions, ResultCacheSizeInMegabytes) {
  EXPECT_EQ(parse_options({}).result_cache_bytes, std::size_t{64} << 20);
  EXPECT_EQ(parse_options({"--result-cache-mb", "0"}).result_cache_bytes, 0u);
  EXPECT_EQ(parse_options({"--result-cache-mb", "3"}).result_cache_bytes, std::size_t{3} << 20);
  EXPECT_THROW(parse_options({"--result-cache-mb", "-1"}), std::invalid_argument);
  EXPECT_NE(usage().find("--result-cache-mb"), std::string::npos);
}

TEST(DaemonOptions, GpuCacheSizeInMegabytes) {
  EXPECT_EQ(parse_options({}).gpu_cache_bytes, std::size_t{1} << 30);
  EXPECT_EQ(parse_options({"--gpu-cache-mb", "16"}).gpu_cache_bytes, std::size_t{16} << 20);
  EXPECT_THROW(parse_options({"--gpu-cache-mb", "0"}), std::invalid_argument);
  EXPECT_NE(usage().find("--gpu-cache-mb"), std::string::npos);
}

TEST(DaemonOptions, RenderThreadsDefaultToOne) {
  EXPECT_EQ(parse_options({}).render_threads, 1u);
  EXPECT_EQ(parse_options({"--render-threads", "3"}).render_threads, 3u);
  EXPECT_THROW(parse_options({"--render-threads", "0"}), std::invalid_argument);
  EXPECT_THROW(parse_options({"--render-threads", "two"}), std::invalid_argument);
}

TEST(DaemonOptions, FramesInFlightAreOneOrTwo) {
  EXPECT_EQ(parse_options({}).frames_in_flight, 1);
  EXPECT_EQ(parse_options({"--frames-in-flight", "2"}).frames_in_flight, 2);
  EXPECT_EQ(parse_options({"--frames-in-flight", "1"}).frames_in_flight, 1);
  EXPECT_THROW(parse_options({"--frames-in-flight", "0"}), std::invalid_argument);
  EXPECT_THROW(parse_options({"--frames-in-flight", "3"}), std::invalid_argument);
  EXPECT_THROW(parse_options({"--frames-in-flight", "two"}), std::invalid_argument);
}

TEST(DaemonOptions, SkinningIsChosenByTheRasterizerUnlessGiven) {
  using Skinning = Options::Skinning;
  EXPECT_EQ(parse_options({}).skinning, Skinning::Auto);
  EXPECT_EQ(parse_options({"--skinning", "gpu"}).skinning, Skinning::Gpu);
  EXPECT_EQ(parse_options({"--skinning", "cpu"}).skinning, Skinning::Cpu);
  EXPECT_EQ(parse_options({"--skinning", "cpu", "--skinning", "auto"}).skinning, Skinning::Auto);
  try {
    parse_options({"--skinning", "vertex"});
    ADD_FAILURE() << "--skinning vertex was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "--skinning expects gpu, cpu or auto, got 'vertex'");
  }
}

TEST(DaemonOptions, StoreBoundInMegabytesFromTheFlagElseTheEnvironment) {
  unsetenv("TOOND_MAX_STORE_MB");
  Options o = parse_options({});
  EXPECT_FALSE(o.max_store_bytes.has_value());
  apply_store_environment(o);
  EXPECT_EQ(o.max_store_bytes, 0u);  // no bound unless asked
  EXPECT_EQ(parse_options({"--max-store-mb", "2"}).max_store_bytes, std::uint64_t{2} << 20);
  EXPECT_THROW(parse_options({"--max-store-mb", "-1"}), std::invalid_argument);
  EXPECT_THROW(parse_options({"--max-store-mb", "2MB"}), std::invalid_argument);

  setenv("TOOND_MAX_STORE_MB", "5", 1);
  o = parse_options({});
  apply_store_environment(o);
  EXPECT_EQ(o.max_store_bytes, std::uint64_t{5} << 20);
  o = parse_options({"--max-store-mb", "0"});
  apply_store_environment(o);
  EXPECT_EQ(o.max_store_bytes, 0u);  // the flag wins
  setenv("TOOND_MAX_STORE_MB", "lots", 1);
  o = parse_options({});
  try {
    apply_store_environment(o);
    ADD_FAILURE() << "TOOND_MAX_STORE_MB=lots was taken";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("TOOND_MAX_STORE_MB"), std::string::npos) << e.what();
  }
  unsetenv("TOOND_MAX_STORE_MB");
  EXPECT_NE(usage().find("--max-store-mb N"), std::string::npos);
  EXPECT_NE(usage().find("TOOND_MAX_STORE_MB"), std::string::npos);
}

// --help and the parser read one table; this checks that what they make of
// it agrees: every flag the parser reads opens a line of --help, and every
// option --help names anywhere is one the parser reads.
TEST(DaemonOptions, HelpNamesExactlyTheFlagsTheParserReads) {
  const std::string help = usage();
  const std::set<std::string> named = help_checks::options_named_in(help);
  for (const text::OptionHelp& flag : flag_list()) {
    EXPECT_NE(help.find("\n  " + flag.written() + " "), std::string::npos) << flag.written();
    for (const std::string_view name : {flag.alias, flag.name}) {
      if (!name.empty()) {
        EXPECT_TRUE(named.count(std::string(name))) << name;
      }
    }
  }
  for (const std::string& name : named) {
    try {
      parse_options({name});
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).find("unknown option"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace toond::app
