// The model store under a bound (StoreOptions::max_bytes, --max-store-mb):
// the least recently used models go first, never one a render holds here
// (a pin) or on another replica sharing the folder (a lease), and what
// cannot be kept is refused whole.
#include <gtest/gtest.h>

#include <unistd.h>

#include <array>
#include <chrono>
#include <filesystem>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <httplib.h>
#include <nlohmann/json.hpp>

#include "http/error_response.h"
#include "scene/store/model_pins.h"
#include "scene/store/model_store.h"
#include "scene/store/model_use.h"
#include "support/store_fixtures.h"

namespace toond::scene {
namespace {

namespace fs = std::filesystem;

using test::padded_model;

class StoreBound : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("toond-bound-" + std::to_string(::getpid()) + "-" + info->name());
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Room for three padded models and their info.json, not four.
  static StoreOptions three_models() {
    StoreOptions options;
    options.max_bytes = 35000;
    return options;
  }

  // Models "a", "b" and "c", stored in that order: room for no more.
  static std::array<std::string, 3> fill(ModelStore& store) {
    return {store.put(padded_model("a")).info.id, store.put(padded_model("b")).info.id,
            store.put(padded_model("c")).info.id};
  }

  // What a render does to a model: pins it when it looks it up, leases it
  // when it is queued, lets go when it is answered.
  static void render(ModelStore& store, const std::string& id) {
    ModelPins pins(store);
    pins.add(id);
    pins.lease();
  }

  // A full store's first model, A, held by `held` while B and C are
  // rendered: A is the least recently used, yet an upload through
  // `uploading` lets B go instead. Returns the upload's id.
  static std::string upload_past_held_model(ModelPins& held, ModelStore& uploading,
                                            const std::array<std::string, 3>& abc) {
    held.add(abc[0]);
    held.lease();
    render(uploading, abc[1]);
    render(uploading, abc[2]);
    const auto d = uploading.put(padded_model("d"));
    EXPECT_EQ(d.evicted, std::vector<std::string>{abc[1]});
    EXPECT_TRUE(uploading.contains(abc[0]));
    return d.info.id;
  }

  std::set<std::string> stored(const ModelStore& store) const {
    std::set<std::string> ids;
    for (const ModelInfo& m : store.list()) ids.insert(m.id);
    return ids;
  }

  // Temporary folders left, once the store's sweeper thread has had a
  // moment to delete the models let go (it does so just after the upload
  // that let them go is answered).
  std::set<std::string> temporary_folders() const {
    std::set<std::string> names;
    for (int tries = 0; tries < 500; ++tries) {
      names.clear();
      for (const auto& e : fs::directory_iterator(dir_ / "models")) {
        const std::string name = e.path().filename().string();
        if (name.starts_with(".tmp-")) names.insert(name);
      }
      if (names.empty()) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return names;
  }

  fs::path dir_;
};

TEST_F(StoreBound, LetsTheLeastRecentlyUsedGoFirstByLastUploadOrRender) {
  ModelStore store(dir_, three_models());
  const auto [a, b, c] = fill(store);
  EXPECT_EQ(stored(store), (std::set<std::string>{a, b, c}));

  // A rendered last: B is now the least recently used.
  render(store, a);
  const auto d = store.put(padded_model("d"));
  EXPECT_TRUE(d.created);
  EXPECT_EQ(d.evicted, std::vector<std::string>{b});
  EXPECT_EQ(stored(store), (std::set<std::string>{a, c, d.info.id}));
  EXPECT_FALSE(store.info(b));
  EXPECT_FALSE(store.load(b));
  EXPECT_FALSE(store.contains(b));

  // C uploaded again counts as a use too: A goes next.
  EXPECT_FALSE(store.put(padded_model("c")).created);
  const auto e = store.put(padded_model("e"));
  EXPECT_EQ(e.evicted, std::vector<std::string>{a});
  EXPECT_EQ(stored(store), (std::set<std::string>{c, d.info.id, e.info.id}));

  EXPECT_LE(store.usage().bytes, three_models().max_bytes);
  EXPECT_EQ(store.usage().models, 3u);
  EXPECT_EQ(store.evictions(), 2u);
  EXPECT_TRUE(temporary_folders().empty());
}

TEST_F(StoreBound, TwoModelsGoWhenOneIsNotEnoughRoom) {
  ModelStore store(dir_, three_models());
  const auto [a, b, c] = fill(store);
  const auto big = store.put(padded_model("big", 20000));
  EXPECT_EQ(big.evicted, (std::vector<std::string>{a, b}));
  EXPECT_EQ(stored(store), (std::set<std::string>{c, big.info.id}));
  EXPECT_LE(store.usage().bytes, three_models().max_bytes);
}

TEST_F(StoreBound, NeverLetsGoAModelARenderHolds) {
  ModelStore store(dir_, three_models());
  const auto models = fill(store);
  const auto& [a, b, c] = models;
  ModelPins held(store);
  const std::string d = upload_past_held_model(held, store, models);

  // Every model that could make room is held: the upload is refused whole,
  // and nothing is let go for it.
  held.add(c);
  held.add(d);
  try {
    store.put(padded_model("e"));
    FAIL() << "stored past the bound";
  } catch (const StoreError& error) {
    EXPECT_EQ(error.kind(), StoreError::Kind::FullOfModelsInUse);
  }
  EXPECT_EQ(stored(store), (std::set<std::string>{a, c, d}));
  EXPECT_TRUE(temporary_folders().empty());
  EXPECT_EQ(store.evictions(), 1u);
}

TEST_F(StoreBound, AModelIsFreeAgainOnceItsLastRenderLetsGo) {
  ModelStore store(dir_, three_models());
  const auto [a, b, c] = fill(store);
  const fs::path leases = dir_ / "models" / a / kLeaseFolder;
  {
    ModelPins first(store);
    first.add(a);
    first.lease();
    {
      ModelPins second(store);
      second.add(a);
      second.lease();
    }
    // One of two renders of A is done: A is still held, here and for
    // every replica.
    EXPECT_FALSE(fs::is_empty(leases));
    render(store, b);
    render(store, c);
    EXPECT_EQ(store.put(padded_model("d")).evicted, std::vector<std::string>{b});
  }
  // Both done: A, the least recently used, goes.
  EXPECT_TRUE(fs::is_empty(leases));
  EXPECT_EQ(store.put(padded_model("e")).evicted, std::vector<std::string>{a});
}

// A request answered from the result cache looks its model up but queues
// no render: this process keeps it meanwhile, other replicas need not.
TEST_F(StoreBound, AModelLookedUpButNotQueuedIsHeldOnlyWhereItWasLookedUp) {
  ModelStore looking(dir_, three_models());
  ModelStore uploading(dir_, three_models());
  const auto [a, b, c] = fill(uploading);
  ModelPins looked_up(looking);
  looked_up.add(a);
  render(uploading, b);
  render(uploading, c);
  EXPECT_TRUE(fs::is_empty(dir_ / "models" / a / kLeaseFolder));
  EXPECT_EQ(looking.put(padded_model("d")).evicted, std::vector<std::string>{b});
  EXPECT_EQ(uploading.put(padded_model("e")).evicted, std::vector<std::string>{a});
}

// Two stores on one folder are two replicas on one volume: neither sees
// the other's pins, only the lease in the model's folder.
TEST_F(StoreBound, AnotherReplicasRenderHoldsItsModelThroughItsLease) {
  ModelStore rendering(dir_, three_models());
  ModelStore uploading(dir_, three_models());
  const auto models = fill(uploading);
  const std::string& a = models[0];
  {
    // The other replica draws A.
    ModelPins held(rendering);
    upload_past_held_model(held, uploading, models);
  }
  // Its render is done: A goes.
  EXPECT_EQ(uploading.put(padded_model("e")).evicted, std::vector<std::string>{a});
  EXPECT_EQ(rendering.usage().models, 3u);
  EXPECT_EQ(rendering.evictions(), 0u);
  EXPECT_EQ(uploading.evictions(), 2u);
}

TEST_F(StoreBound, ALeaseOlderThanItsExpiryIsADeadReplicasAndHoldsNothing) {
  StoreOptions options = three_models();
  options.lease_expiry = std::chrono::seconds(60);
  ModelStore uploading(dir_, options);
  const auto [a, b, c] = fill(uploading);
  {
    // A replica took A and was killed before it let go: its lease stays.
    ModelStore dying(dir_, options);
    dying.pin(a);
    dying.lease(a);
  }
  const fs::path lease_folder = dir_ / "models" / a / kLeaseFolder;
  ASSERT_FALSE(fs::is_empty(lease_folder));
  render(uploading, b);
  render(uploading, c);
  // Fresh, the lease holds A, the least recently used.
  const auto d = uploading.put(padded_model("d"));
  EXPECT_EQ(d.evicted, std::vector<std::string>{b});
  // Older than the expiry, it does not.
  for (const auto& lease : fs::directory_iterator(lease_folder)) {
    fs::last_write_time(lease.path(), fs::file_time_type::clock::now() - std::chrono::minutes(5));
  }
  EXPECT_EQ(uploading.put(padded_model("e")).evicted, std::vector<std::string>{a});
}

TEST_F(StoreBound, AModelLargerThanTheWholeBoundIsRefusedAndNothingIsLeft) {
  ModelStore store(dir_, three_models());
  const std::string a = store.put(padded_model("a")).info.id;
  try {
    store.put(padded_model("huge", 40000));
    FAIL() << "stored a model larger than the bound";
  } catch (const StoreError& error) {
    EXPECT_EQ(error.kind(), StoreError::Kind::LargerThanStore);
    EXPECT_NE(std::string(error.what()).find("35000"), std::string::npos) << error.what();
  }
  EXPECT_EQ(stored(store), std::set<std::string>{a});
  EXPECT_TRUE(temporary_folders().empty());
}

TEST_F(StoreBound, WithoutABoundNothingIsLetGo) {
  ModelStore store(dir_);
  for (int i = 0; i < 8; ++i) store.put(padded_model("m" + std::to_string(i)));
  EXPECT_EQ(store.usage().models, 8u);
  EXPECT_GT(store.usage().bytes, 80000u);
  EXPECT_EQ(store.evictions(), 0u);
  EXPECT_EQ(store.max_bytes(), 0u);
}

TEST_F(StoreBound, UsageCountsTheFilesOfEveryReplicasModels) {
  ModelStore a(dir_);
  ModelStore b(dir_);
  const std::string id = a.put(padded_model("a")).info.id;
  std::uint64_t on_disk = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir_ / "models" / id)) {
    if (e.is_regular_file()) on_disk += e.file_size();
  }
  EXPECT_EQ(b.usage().bytes, on_disk);
  EXPECT_EQ(b.usage().models, 1u);
  EXPECT_TRUE(b.remove(id));
  EXPECT_EQ(a.usage().bytes, 0u);
}

TEST_F(StoreBound, UploadsInParallelStayUnderTheBound) {
  ModelStore store(dir_, three_models());
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      for (int i = 0; i < 4; ++i) store.put(padded_model("t" + std::to_string(t) + "-" + std::to_string(i)));
    });
  }
  for (auto& t : threads) t.join();
  // One pass at a time lets go exactly what each upload needs: the store
  // ends full, every upload counted once, nothing left behind.
  EXPECT_LE(store.usage().bytes, three_models().max_bytes);
  EXPECT_EQ(store.usage().models, 3u);
  EXPECT_EQ(store.evictions(), 13u);
  EXPECT_TRUE(temporary_folders().empty());
}

// Another replica lets a model go by renaming its folder away first: a
// reader then finds no model, never part of one, and no error.
TEST_F(StoreBound, AModelTakenAwayWhileItIsReadIsNotFound) {
  ModelStore store(dir_);
  const std::string id = store.put(padded_model("a")).info.id;
  fs::rename(dir_ / "models" / id, dir_ / "models" / (".tmp-removed-" + id));
  EXPECT_FALSE(store.info(id));
  EXPECT_FALSE(store.load(id));
  EXPECT_FALSE(store.contains(id));
}

// A damaged model (a file missing from its folder) is an error, but one
// whose message names the bundle's file, never where the store keeps it.
TEST_F(StoreBound, ADamagedModelsErrorNamesNoServerPath) {
  ModelStore store(dir_);
  const std::string id = store.put(padded_model("a")).info.id;
  fs::remove(dir_ / "models" / id / "files" / "m.obj");
  try {
    store.load(id);
    FAIL() << "loaded a damaged model";
  } catch (const StoreError& error) {
    EXPECT_EQ(error.kind(), StoreError::Kind::Failed);
    EXPECT_NE(std::string(error.what()).find("m.obj"), std::string::npos) << error.what();
    EXPECT_EQ(std::string(error.what()).find(dir_.string()), std::string::npos) << error.what();
    EXPECT_NE(error.detail().find(dir_.string()), std::string::npos) << error.detail();
  }
}

// What a client reads of the store's refusals: the status and code that
// say what to do, Retry-After where waiting helps, and never a server path
// (the detail that has one goes to the log).
template <typename E>
nlohmann::json answer_for(const E& e, httplib::Response& res) {
  http::write_exception(res, std::make_exception_ptr(e));
  return nlohmann::json::parse(res.body).at("error");
}

TEST(StoreAnswer, AFullVolumeIs507StorageFullNamingNoPath) {
  httplib::Response res;
  const StoreError full(StoreError::Kind::VolumeFull,
                        "the volume the models are stored on is full (No space left on device)",
                        "cannot write /srv/toond/models/.tmp-x/files/m.obj: No space left on device");
  const auto error = answer_for(full, res);
  EXPECT_EQ(res.status, 507);
  EXPECT_EQ(error.at("code"), "storage_full");
  EXPECT_EQ(error.at("message").get<std::string>().find('/'), std::string::npos) << error;
  EXPECT_FALSE(res.has_header("Retry-After"));
}

TEST(StoreAnswer, ABoundHeldByRendersIs507WithRetryAfter) {
  httplib::Response res;
  const auto error = answer_for(StoreError(StoreError::Kind::FullOfModelsInUse, "renders hold it"), res);
  EXPECT_EQ(res.status, 507);
  EXPECT_EQ(error.at("code"), "storage_full");
  EXPECT_NE(error.at("message").get<std::string>().find("--max-store-mb"), std::string::npos) << error;
  EXPECT_EQ(res.get_header_value("Retry-After"), "5");
}

TEST(StoreAnswer, AModelLargerThanTheBoundIs413NamingTheFlag) {
  httplib::Response res;
  const auto error = answer_for(StoreError(StoreError::Kind::LargerThanStore, "too big"), res);
  EXPECT_EQ(res.status, 413);
  EXPECT_EQ(error.at("code"), "limit_exceeded");
  EXPECT_EQ(error.at("limit"), "--max-store-mb");
}

TEST(StoreAnswer, OtherFileErrorsAre500sNamingNoPath) {
  httplib::Response failed;
  const auto store_error =
      answer_for(StoreError(StoreError::Kind::Failed, "the model could not be stored (Permission denied)",
                            "cannot create /srv/toond/models/.tmp-x/info.json: Permission denied"),
                 failed);
  EXPECT_EQ(failed.status, 500);
  EXPECT_EQ(store_error.at("message"), "the model could not be stored (Permission denied)");

  httplib::Response res;
  const auto error = answer_for(
      fs::filesystem_error("cannot open", "/srv/toond/models/x", std::make_error_code(std::errc::permission_denied)),
      res);
  EXPECT_EQ(res.status, 500);
  EXPECT_EQ(error.at("code"), "internal");
  EXPECT_EQ(error.at("message").get<std::string>().find("/srv"), std::string::npos) << error;
}

}  // namespace
}  // namespace toond::scene
