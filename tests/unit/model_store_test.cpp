#include <gtest/gtest.h>

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <set>
#include <thread>

#include "scene/import/demo_model.h"
#include "scene/reading/import_error.h"
#include "scene/store/model_store.h"

namespace toond::scene {
namespace {

namespace fs = std::filesystem;

const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

Bundle triangle_bundle(const std::string& extra = {}) {
  Bundle bundle;
  bundle.add("tri.obj", kTriangle + extra);
  return bundle;
}

class ModelStoreTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("toond-store-" + std::to_string(::getpid()) + "-" + info->name());
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::set<std::string> entries() const {
    std::set<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_ / "models")) names.insert(e.path().filename().string());
    return names;
  }

  fs::path dir_;
};

TEST(BundleId, IsContentAddressed) {
  const std::string id = bundle_id(triangle_bundle());
  ASSERT_EQ(id.size(), 32u);
  EXPECT_EQ(id.find_first_not_of("0123456789abcdef"), std::string::npos);
  EXPECT_EQ(bundle_id(triangle_bundle()), id);
  EXPECT_NE(bundle_id(triangle_bundle("# changed\n")), id);

  Bundle renamed;
  renamed.add("other.obj", kTriangle);
  EXPECT_NE(bundle_id(renamed), id);

  // Order of upload does not matter; paths are compared normalised.
  Bundle ab;
  ab.add("a.obj", kTriangle);
  ab.add("t\\x.png", "x");
  Bundle ba;
  ba.add("./t/x.png", "x");
  ba.add("a.obj", kTriangle);
  EXPECT_EQ(bundle_id(ab), bundle_id(ba));

  // Records cannot run into each other: moving a byte from one file's name
  // into the previous file's content changes the id.
  Bundle split1;
  split1.add("a", "bc");
  split1.add("d", "");
  Bundle split2;
  split2.add("a", "b");
  split2.add("cd", "");
  EXPECT_NE(bundle_id(split1), bundle_id(split2));
}

TEST_F(ModelStoreTest, PutStoresOnceAndReportsTheModel) {
  ModelStore store(dir_);
  const Bundle bundle = make_demo_bundle();
  const auto first = store.put(bundle);
  EXPECT_TRUE(first.created);
  EXPECT_EQ(first.info.id, bundle_id(bundle));
  EXPECT_EQ(first.info.triangles, 2220u);
  EXPECT_EQ(first.info.materials, 2u);
  EXPECT_EQ(first.info.textures, 1u);
  EXPECT_EQ(first.info.bytes, bundle.total_bytes());
  EXPECT_EQ(first.info.files, (std::vector<std::string>{"demo.mtl", "demo.obj", "ramps/sharp.png", "textures/demo.png",
                                                        "textures/floor.png"}));
  // The demo carries a ramp and a floor for requests to name: the one
  // warning says how.
  ASSERT_EQ(first.info.warnings.size(), 1u);
  EXPECT_NE(first.info.warnings[0].find("no material uses the images 'ramps/sharp.png', 'textures/floor.png'"),
            std::string::npos)
      << first.info.warnings[0];
  EXPECT_NE(first.info.warnings[0].find("shading.ramp_image or floor.texture"), std::string::npos);
  EXPECT_TRUE(fs::is_regular_file(dir_ / "models" / first.info.id / "info.json"));
  EXPECT_TRUE(fs::is_regular_file(dir_ / "models" / first.info.id / "files" / "textures" / "demo.png"));

  const auto second = store.put(bundle);
  EXPECT_FALSE(second.created);
  EXPECT_EQ(second.info.to_json(), first.info.to_json());
  EXPECT_EQ(store.list().size(), 1u);
}

TEST_F(ModelStoreTest, SurvivesReopening) {
  std::string id;
  {
    ModelStore store(dir_);
    id = store.put(make_demo_bundle()).info.id;
    store.put(triangle_bundle());
  }
  ModelStore reopened(dir_);
  const auto models = reopened.list();
  ASSERT_EQ(models.size(), 2u);
  EXPECT_LT(models[0].id, models[1].id);
  const auto info = reopened.info(id);
  ASSERT_TRUE(info);
  EXPECT_EQ(info->triangles, 2220u);
  const auto loaded = reopened.load(id);
  ASSERT_TRUE(loaded);
  EXPECT_EQ(loaded->files(), make_demo_bundle().files());
  EXPECT_EQ(bundle_id(*loaded), id);
}

TEST_F(ModelStoreTest, RemoveDeletesForGood) {
  ModelStore store(dir_);
  const std::string id = store.put(triangle_bundle()).info.id;
  EXPECT_TRUE(store.remove(id));
  EXPECT_FALSE(store.info(id));
  EXPECT_FALSE(store.load(id));
  EXPECT_TRUE(store.list().empty());
  EXPECT_TRUE(entries().empty());
  EXPECT_FALSE(store.remove(id));
  // And it can come back.
  EXPECT_TRUE(store.put(triangle_bundle()).created);
  EXPECT_TRUE(ModelStore(dir_).info(id));
}

TEST_F(ModelStoreTest, LeftoverTemporaryFoldersAreCleaned) {
  fs::create_directories(dir_ / "models" / ".tmp-0123-abc" / "files");
  std::ofstream(dir_ / "models" / ".tmp-0123-abc" / "files" / "half.obj") << "v 0 0";
  fs::create_directories(dir_ / "models" / ".tmp-removed-xyz");
  const auto long_ago = fs::file_time_type::clock::now() - ModelStore::kStaleTempAge - std::chrono::minutes(1);
  fs::last_write_time(dir_ / "models" / ".tmp-0123-abc", long_ago);
  fs::last_write_time(dir_ / "models" / ".tmp-removed-xyz", long_ago);
  ModelStore store(dir_);
  EXPECT_TRUE(entries().empty());
  EXPECT_TRUE(store.list().empty());
}

// Replicas share the data directory: one starting up must not delete the
// upload another is writing right now.
TEST_F(ModelStoreTest, AFreshTemporaryFolderIsAnotherProcesssUploadAndStays) {
  fs::create_directories(dir_ / "models" / ".tmp-0123-abc" / "files");
  std::ofstream(dir_ / "models" / ".tmp-0123-abc" / "files" / "half.obj") << "v 0 0";
  ModelStore store(dir_);
  EXPECT_EQ(entries(), std::set<std::string>{".tmp-0123-abc"});
  EXPECT_TRUE(store.list().empty());
}

TEST_F(ModelStoreTest, TwoStoresOnOneFolderSeeEachOthersChanges) {
  ModelStore a(dir_);
  ModelStore b(dir_);
  const std::string id = a.put(triangle_bundle()).info.id;
  EXPECT_TRUE(b.contains(id));
  ASSERT_EQ(b.list().size(), 1u);
  EXPECT_TRUE(b.load(id));
  EXPECT_FALSE(b.put(triangle_bundle()).created);
  EXPECT_TRUE(b.remove(id));
  EXPECT_FALSE(a.contains(id));
  EXPECT_TRUE(a.list().empty());
}

TEST_F(ModelStoreTest, RejectedBundleLeavesNothingBehind) {
  ModelStore store(dir_);
  Bundle bad;
  bad.add("bad.obj", "v 0 0 0\nf 1 2 3\n");
  EXPECT_THROW(store.put(bad), ImportError);
  Bundle no_obj;
  no_obj.add("readme.txt", "hello");
  EXPECT_THROW(store.put(no_obj), ImportError);
  EXPECT_TRUE(entries().empty());
}

TEST_F(ModelStoreTest, IdsFromOutsideCannotEscape) {
  ModelStore store(dir_);
  const std::string id = store.put(triangle_bundle()).info.id;
  std::string upper = id;
  for (auto& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (const std::string& bad : {std::string(".."), std::string("../models"), std::string(""), upper, id.substr(0, 31),
                                 id + "0", std::string("/etc")}) {
    EXPECT_FALSE(store.info(bad)) << bad;
    EXPECT_FALSE(store.load(bad)) << bad;
    EXPECT_FALSE(store.remove(bad)) << bad;
  }
  EXPECT_TRUE(store.info(id));
}

TEST_F(ModelStoreTest, ConcurrentPutsOfOneBundleCreateItOnce) {
  ModelStore store(dir_);
  const Bundle bundle = make_demo_bundle();
  std::atomic<int> created{0};
  std::vector<std::thread> threads;
  for (int i = 0; i < 4; ++i) {
    threads.emplace_back([&] {
      if (store.put(bundle).created) ++created;
    });
  }
  for (auto& t : threads) t.join();
  EXPECT_EQ(created.load(), 1);
  EXPECT_EQ(entries(), std::set<std::string>{bundle_id(bundle)});
}

TEST(ModelInfo, JsonRoundTrip) {
  ModelInfo info;
  info.id = "0123456789abcdef0123456789abcdef";
  info.triangles = 12;
  info.materials = 2;
  info.textures = 1;
  info.bytes = 345;
  info.files = {"a.obj", "t/x.png"};
  info.warnings = {"something"};
  // Import resolves the format's convention, so a stored record always names its axis.
  info.choices.up = ImportChoices::Up::Z;
  const nlohmann::json j = info.to_json();
  EXPECT_EQ(j.at("id"), info.id);
  EXPECT_EQ(j.at("triangles"), 12);
  EXPECT_EQ(j.at("up"), "z");
  EXPECT_EQ(ModelInfo::from_json(j).to_json(), j);
}

TEST(ModelInfo, ARecordWithoutAnUpAxisReadsAsItWasImported) {
  nlohmann::json j = {{"id", "0123456789abcdef0123456789abcdef"},
                      {"triangles", 1},
                      {"materials", 1},
                      {"textures", 0},
                      {"bytes", 1},
                      {"files", {"a.obj"}}};
  EXPECT_EQ(ModelInfo::from_json(j).choices.up, ImportChoices::Up::Y);
  j["files"] = {"part.3mf"};
  EXPECT_EQ(ModelInfo::from_json(j).choices.up, ImportChoices::Up::Z);
}

}  // namespace
}  // namespace toond::scene
