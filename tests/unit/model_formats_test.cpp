// The list of model-file extensions has one source (bundle_paths/
// model_formats.h) for the daemon and toon; the web page keeps a copy in
// JavaScript, held equal to it here.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "bundle_paths/model_formats.h"

namespace toond::bundle_paths {
namespace {

TEST(ModelFormats, OwnAndAssimpFormatsAreModelFilesInAnyCase) {
  for (const char* path : {"a.obj", "b/c.GLB", "d.Stl", "e.ply", "f.fbx", "g.DAE", "h.3ds", "i.3mf", "j.off"}) {
    EXPECT_TRUE(is_model_file(path)) << path;
  }
  for (const char* path : {"a.mtl", "b.png", "c.bin", "d.blend", "e.txt", "fbx", ".fbx.png"}) {
    EXPECT_FALSE(is_model_file(path)) << path;
  }
  EXPECT_TRUE(has_any_extension("x.FBX", assimp_model_extensions()));
  EXPECT_FALSE(has_any_extension("x.obj", assimp_model_extensions()));
}

TEST(ModelFormats, TheWebPageListsTheSameExtensions) {
  std::ifstream in(TOOND_WEB_DIR "/upload.js");
  std::ostringstream text;
  text << in.rdbuf();
  const std::string js = text.str();
  const auto start = js.find("export const MODEL_EXTENSIONS = [");
  ASSERT_NE(start, std::string::npos);
  const std::string list = js.substr(start, js.find("];", start) - start);
  std::vector<std::string> page;
  const std::regex quoted("'([a-z0-9]+)'");
  for (auto it = std::sregex_iterator(list.begin(), list.end(), quoted); it != std::sregex_iterator(); ++it) {
    page.push_back("." + (*it)[1].str());
  }
  std::vector<std::string> ours;
  for (const auto& list_of : {own_model_extensions(), assimp_model_extensions()}) {
    for (const std::string_view extension : list_of) ours.emplace_back(extension);
  }
  EXPECT_EQ(page, ours);
}

}  // namespace
}  // namespace toond::bundle_paths
