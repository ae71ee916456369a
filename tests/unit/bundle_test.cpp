#include <gtest/gtest.h>

#include <string>

#include "scene/reading/bundle.h"
#include "scene/reading/import_error.h"

namespace toond::scene {
namespace {

using namespace std::string_literals;

TEST(Bundle, AddNormalisesAndFinds) {
  Bundle bundle;
  bundle.add("models\\dog\\dog.obj", "o");
  bundle.add("./models/dog/Textures/colormap.png", "png");
  ASSERT_NE(bundle.find("models/dog/dog.obj"), nullptr);
  EXPECT_EQ(*bundle.find("models/dog/dog.obj"), "o");
  EXPECT_EQ(bundle.find("models\\dog\\dog.obj"), nullptr);  // find takes bundle paths only
  EXPECT_EQ(bundle.files().size(), 2u);
  EXPECT_EQ(bundle.total_bytes(), 4u);
  EXPECT_FALSE(bundle.empty());
}

TEST(Bundle, AddRejectsUnsafeNamesWithImportError) {
  for (const std::string& bad : {"../x"s, "/etc/passwd"s, "C:\\x"s, "a/../../x"s, "a\0b.obj"s, ""s}) {
    Bundle bundle;
    try {
      bundle.add(bad, "x");
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const ImportError& e) {
      EXPECT_EQ(e.file().find('\0'), std::string::npos);
      EXPECT_NE(std::string(e.what()).find("safe relative path"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(bundle.empty());
  }
}

TEST(Bundle, AddRejectsDuplicatesAndFileFolderClashes) {
  Bundle bundle;
  bundle.add("a/b.png", "1");
  EXPECT_THROW(bundle.add("a\\b.png", "2"), ImportError);
  EXPECT_THROW(bundle.add("a", "3"), ImportError);          // "a" is already a folder
  EXPECT_THROW(bundle.add("a/b.png/c", "4"), ImportError);  // "a/b.png" is a file
  EXPECT_EQ(*bundle.find("a/b.png"), "1");
  EXPECT_EQ(bundle.files().size(), 1u);
}

class BundleResolve : public ::testing::Test {
 protected:
  void SetUp() override {
    bundle_.add("model/spot.obj", "");
    bundle_.add("model/spot.mtl", "");
    bundle_.add("model/Textures/Colormap.PNG", "");
    bundle_.add("textures/shared.png", "");
    bundle_.add("top.png", "");
    bundle_.add("exact.png", "");
    bundle_.add("EXACT.png", "");
  }
  Bundle bundle_;
};

TEST_F(BundleResolve, RelativeToTheReferringFile) {
  EXPECT_EQ(bundle_.resolve("model/spot.obj", "spot.mtl"), "model/spot.mtl");
  EXPECT_EQ(bundle_.resolve("model/spot.obj", "./spot.mtl"), "model/spot.mtl");
  EXPECT_EQ(bundle_.resolve("model/spot.mtl", "../textures/shared.png"), "textures/shared.png");
  EXPECT_EQ(bundle_.resolve("top.obj", "top.png"), "top.png");
  // Not found beside the referring file, even though it exists elsewhere.
  EXPECT_EQ(bundle_.resolve("model/spot.obj", "top.png"), std::nullopt);
}

TEST_F(BundleResolve, BackslashesAndCaseInsensitiveFallback) {
  EXPECT_EQ(bundle_.resolve("model/spot.mtl", "Textures\\Colormap.PNG"), "model/Textures/Colormap.PNG");
  EXPECT_EQ(bundle_.resolve("model/spot.mtl", "textures/colormap.png"), "model/Textures/Colormap.PNG");
  EXPECT_EQ(bundle_.resolve("model/spot.mtl", ".\\TEXTURES\\COLORMAP.png"), "model/Textures/Colormap.PNG");
  EXPECT_EQ(bundle_.resolve("model/SPOT.obj", "SPOT.MTL"), "model/spot.mtl");
}

TEST_F(BundleResolve, ExactMatchWinsOverCaseInsensitive) {
  EXPECT_EQ(bundle_.resolve("a.mtl", "EXACT.png"), "EXACT.png");
  EXPECT_EQ(bundle_.resolve("a.mtl", "exact.png"), "exact.png");
}

TEST_F(BundleResolve, NeverLeavesTheBundle) {
  EXPECT_EQ(bundle_.resolve("model/spot.mtl", "../../top.png"), std::nullopt);
  EXPECT_EQ(bundle_.resolve("spot.obj", "../top.png"), std::nullopt);
  EXPECT_EQ(bundle_.resolve("model/spot.mtl", "/top.png"), std::nullopt);
  EXPECT_EQ(bundle_.resolve("model/spot.mtl", "/etc/passwd"), std::nullopt);
  EXPECT_EQ(bundle_.resolve("model/spot.mtl", "C:\\top.png"), std::nullopt);
  EXPECT_EQ(bundle_.resolve("model/spot.mtl", "C:top.png"), std::nullopt);
  EXPECT_EQ(bundle_.resolve("model/spot.mtl", "spot.mtl\0.png"s), std::nullopt);
  EXPECT_EQ(bundle_.resolve("model/spot.mtl", ""), std::nullopt);
  EXPECT_EQ(bundle_.resolve("model/spot.mtl", "missing.png"), std::nullopt);
}

}  // namespace
}  // namespace toond::scene
