// A full disk, for real: the data directory on a 3 MB tmpfs. An upload that
// does not fit is a 507 storage_full naming no server path; nothing of it is
// left; the models stored before still render; room made again is used
// again. Mounting needs root (CAP_SYS_ADMIN), as here and in CI; elsewhere
// the test says it was skipped and why.
#include <gtest/gtest.h>

#include <sys/mount.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "store_checks.h"
#include "support/prometheus_text.h"
#include "test_client.h"

namespace toond::test {
namespace {

namespace fs = std::filesystem;

class FullVolume : public ::testing::Test {
 protected:
  void SetUp() override {
    mount_point_ = make_temp_dir("toond-full-volume");
    if (::mount("tmpfs", mount_point_.c_str(), "tmpfs", MS_NOSUID | MS_NODEV, "size=3m") != 0) {
      const int error = errno;
      fs::remove_all(mount_point_);
      mount_point_.clear();
      GTEST_SKIP() << "cannot mount a 3 MB tmpfs for the data directory (" << std::strerror(error)
                   << "); this test needs root (CAP_SYS_ADMIN)";
    }
  }
  void TearDown() override {
    if (mount_point_.empty()) return;
    ::umount2(mount_point_.c_str(), MNT_DETACH);
    fs::remove_all(mount_point_);
  }

  fs::path mount_point_;
};

TEST_F(FullVolume, AnUploadThatDoesNotFitIs507NamingNoPathAndLosesNothing) {
  TOOND_REQUIRE_SHARED_MODELS();
  std::vector<std::string> stored;
  {
    Daemon daemon(mount_point_);
    auto client = daemon.client();
    std::optional<httplib::Result> refused;
    for (int angle = 1; angle <= 30; ++angle) {
      auto res = upload_teapot(client, angle);
      ASSERT_TRUE(res);
      if (res->status != 201) {
        refused.emplace(std::move(res));
        break;
      }
      stored.push_back(nlohmann::json::parse(res->body).at("id"));
    }
    ASSERT_TRUE(refused) << "30 teapots fitted on a 3 MB volume";
    EXPECT_GE(stored.size(), 10u);
    EXPECT_EQ((*refused)->status, 507) << (*refused)->body;
    const nlohmann::json error = error_of(*refused);
    EXPECT_EQ(error.value("code", ""), "storage_full");
    const std::string message = error.value("message", "");
    EXPECT_EQ(message.find('/'), std::string::npos) << "the message names a path: " << message;
    EXPECT_EQ(message.find(".tmp-"), std::string::npos) << message;
    EXPECT_EQ(error.value("path", "?"), "");

    // Nothing of the refused upload is left: the store holds exactly the
    // models answered 201, each whole.
    EXPECT_EQ(store_entries(mount_point_), std::set<std::string>(stored.begin(), stored.end()));
    for (const std::string& id : stored) {
      auto res = post_json(client, "/models/" + id + "/render", {{"width", 64}, {"height", 64}});
      ASSERT_TRUE(res);
      EXPECT_EQ(res->status, 200) << id << ": " << res->body;
    }

    // Upload and render in one call is refused the same way, and the
    // daemon goes on rendering.
    httplib::MultipartFormDataItems both{
        {"file", read_file(shared_models_dir() / "utah-teapot" / "teapot.obj"), "teapot.obj", ""},
        {"params", R"({"width":64,"height":64})", "", "application/json"}};
    auto render_upload = client.Post("/render", both);
    ASSERT_TRUE(render_upload);
    EXPECT_EQ(render_upload->status, 507) << render_upload->body;
    EXPECT_EQ(store_entries(mount_point_).size(), stored.size());
    render_ok(client, {{"width", 64}, {"height", 64}});

    const std::string metrics = scrape_when(client, [](const std::string&) { return true; });
    EXPECT_EQ(sample_value(metrics, "toond_store_refusals_total{reason=\"volume_full\"}"), 2.0);
    EXPECT_LT(sample_value(metrics, "toond_store_volume_free_bytes").value_or(1e12), 300e3);

    // Room made by a delete is used again.
    ASSERT_EQ(client.Delete(("/models/" + stored.front()).c_str())->status, 200);
    auto again = upload_teapot(client, 100);
    ASSERT_TRUE(again);
    EXPECT_EQ(again->status, 201) << again->body;
    daemon.stop();
  }
  // And a restart finds every model whole.
  Daemon restarted(mount_point_);
  auto client = restarted.client();
  auto list = client.Get("/models");
  ASSERT_TRUE(list);
  EXPECT_EQ(nlohmann::json::parse(list->body).at("models").size(), stored.size());
  restarted.stop();
}

}  // namespace
}  // namespace toond::test
