#pragma once
// HTTP helpers shared by the integration tests.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <httplib.h>
#include <nlohmann/json.hpp>

#include "image/image.h"
#include "support/daemon.h"

namespace toond::test {

// One daemon shared by every test of a suite: starting llvmpipe and the
// demo import once keeps the suite fast.
class SharedDaemonTest : public ::testing::Test {
 public:
  static void SetUpTestSuite() { daemon_ = std::make_unique<Daemon>(); }
  static void TearDownTestSuite() { daemon_.reset(); }

 protected:
  static Daemon& daemon() { return *daemon_; }
  static inline std::unique_ptr<Daemon> daemon_;
};

// Uploads the named files of a folder (paths relative to it) as a bundle.
httplib::Result upload_files(httplib::Client& client, const std::filesystem::path& folder,
                             const std::vector<std::string>& files);
// Uploads every file of a shared model folder whose extension is a model
// or image file (SOURCE.txt, licences and READMEs are left out).
httplib::Result upload_model_folder(httplib::Client& client, const std::filesystem::path& folder);

// Uploads an OBJ given as text, as a one-file bundle; returns the model id
// (empty, with a test failure, when the upload fails).
std::string upload_obj_text(httplib::Client& client, const std::string& obj, const std::string& name = "model.obj");

httplib::Result post_json(httplib::Client& client, const std::string& path, const nlohmann::json& body);

// POST /render that must succeed; returns the decoded PNG.
image::Image render_ok(httplib::Client& client, const nlohmann::json& params);

// One frame of a sprite sheet: the atlas rectangle `rect` ({x, y, w, h})
// cut out of `sheet`.
image::Image tile_of(const image::Image& sheet, const nlohmann::json& rect);

// The text of the PNG's tEXt chunk named `key`, read from the chunk list
// itself rather than through the daemon's own codec; none when absent.
std::optional<std::string> png_text(const std::string& png, const std::string& key);

// The "error" object of a JSON error answer.
nlohmann::json error_of(const httplib::Result& res);

}  // namespace toond::test
