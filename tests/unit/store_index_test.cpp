// The model store's index (issue 55): its records, its order, and the file
// on the volume read at start when intact, rebuilt (saying so) when missing
// or damaged, and rewritten once it holds many more records than models.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "scene/store/model_pins.h"
#include "scene/store/model_store.h"
#include "scene/store/store_index.h"
#include "scene/store/store_journal.h"
#include "support/store_fixtures.h"

namespace toond::scene {
namespace {

namespace fs = std::filesystem;
using test::models_on_disk;
using test::padded_model;
using test::total_bytes;

const std::string kA(32, 'a');
const std::string kB(32, 'b');
const std::string kC(32, 'c');

TEST(JournalRecord, ReadsBackWhatWasWritten) {
  const JournalRecord present{JournalRecord::Kind::Present, kA, 12345, {1700000000, 999999999}};
  const std::string line = format_record(present);
  ASSERT_EQ(line.back(), '\n');
  const auto read = parse_record(std::string_view(line).substr(0, line.size() - 1));
  ASSERT_TRUE(read);
  EXPECT_EQ(read->kind, JournalRecord::Kind::Present);
  EXPECT_EQ(read->id, kA);
  EXPECT_EQ(read->bytes, 12345u);
  EXPECT_EQ(read->last_use.tv_sec, 1700000000);
  EXPECT_EQ(read->last_use.tv_nsec, 999999999);

  const std::string absent = format_record({JournalRecord::Kind::Absent, kB, 0, {}});
  const auto gone = parse_record(std::string_view(absent).substr(0, absent.size() - 1));
  ASSERT_TRUE(gone);
  EXPECT_EQ(gone->kind, JournalRecord::Kind::Absent);
  EXPECT_EQ(gone->id, kB);
}

TEST(JournalRecord, AChangedOrCutLineIsNotARecord) {
  std::string line = format_record({JournalRecord::Kind::Intent, kA, 2048, {1700000000, 5}});
  line.pop_back();
  std::string changed = line;
  changed[40] = changed[40] == '1' ? '2' : '1';  // a digit of the size
  EXPECT_FALSE(parse_record(changed));
  EXPECT_FALSE(parse_record(line.substr(0, line.size() - 3)));
  EXPECT_FALSE(parse_record(""));
  // A well-formed line about something that is not a model id.
  std::string path = format_record({JournalRecord::Kind::Absent, std::string(32, 'x'), 0, {}});
  path.pop_back();
  EXPECT_FALSE(parse_record(path));
}

TEST(StoreIndex, KeepsTheLeastRecentlyUsedFirstAndTheSum) {
  StoreIndex index;
  index.put(kA, 100, {30, 0});
  index.put(kB, 200, {10, 0});
  index.put(kC, 400, {20, 0});
  EXPECT_EQ(index.usage().models, 3u);
  EXPECT_EQ(index.usage().bytes, 700u);
  EXPECT_EQ(index.order().begin()->id, kB);

  // B used now: C is the least recently used, and the iterator to B's new
  // place is handed back.
  const auto moved = index.restamp(kB, {40, 0});
  EXPECT_EQ(moved->id, kB);
  EXPECT_EQ(std::next(moved), index.order().end());
  EXPECT_EQ(index.order().begin()->id, kC);

  index.erase(kC);
  index.put(kA, 150, {30, 0});  // a model stored again replaces what was known
  EXPECT_EQ(index.usage().models, 2u);
  EXPECT_EQ(index.usage().bytes, 350u);
  EXPECT_EQ(index.bytes(kC), 0u);
  std::vector<std::string> order;
  for (const StoredModel& m : index.models()) order.push_back(m.id);
  EXPECT_EQ(order, (std::vector<std::string>{kA, kB}));
}

class StoreIndexFile : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("toond-index-" + std::to_string(::getpid()) + "-" + info->name());
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Options that keep what the store logs.
  StoreOptions logged(std::uint64_t max_bytes = 0) {
    StoreOptions options;
    options.max_bytes = max_bytes;
    options.log = [this](const std::string& line) { log_.push_back(line); };
    return options;
  }

  // Three models stored by one replica that is then gone.
  void store_three() {
    ModelStore store(dir_, logged());
    for (const char* tag : {"a", "b", "c"}) store.put(padded_model(tag));
    log_.clear();
  }

  fs::path index_path() const { return dir_ / "models.index"; }
  std::string index_text() const {
    std::ifstream in(index_path(), std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }
  void write_index(const std::string& text) const { std::ofstream(index_path(), std::ios::binary) << text; }

  fs::path dir_;
  std::vector<std::string> log_;
};

TEST_F(StoreIndexFile, AnIntactIndexIsReadNotRebuilt) {
  store_three();
  // The index, not a walk of the models, is what the next start reads: a
  // size only the index holds is what it counts.
  std::string text = index_text();
  const std::size_t start = text.find("\n+ ") + 1;
  const std::string first = text.substr(start, text.find('\n', start) - start);
  auto record = parse_record(first);
  ASSERT_TRUE(record);
  const std::uint64_t real = record->bytes;
  record->bytes += 1000;
  std::string changed = format_record(*record);
  changed.pop_back();
  text.replace(text.find(first), first.size(), changed);
  write_index(text);

  ModelStore store(dir_, logged());
  EXPECT_TRUE(log_.empty()) << log_.front();
  EXPECT_EQ(store.usage().models, 3u);
  EXPECT_EQ(store.usage().bytes, total_bytes(models_on_disk(dir_)) + 1000) << "real size " << real;
}

TEST_F(StoreIndexFile, AMissingIndexIsRebuiltFromTheModelsAndSaysSo) {
  store_three();
  fs::remove(index_path());
  ModelStore store(dir_, logged());
  ASSERT_EQ(log_.size(), 1u);
  EXPECT_NE(log_[0].find("no index"), std::string::npos) << log_[0];
  EXPECT_NE(log_[0].find("rebuilt it from the 3 models"), std::string::npos) << log_[0];
  EXPECT_EQ(store.usage().models, 3u);
  EXPECT_EQ(store.usage().bytes, total_bytes(models_on_disk(dir_)));
  EXPECT_TRUE(fs::exists(index_path()));
}

TEST_F(StoreIndexFile, ADamagedIndexIsRebuiltFromTheModelsAndSaysSo) {
  store_three();
  // A line in the middle garbled: what follows it cannot be trusted either.
  std::string text = index_text();
  const std::size_t second_record = text.find('\n', text.find('\n') + 1) + 1;
  text[second_record + 3] ^= 0x01;
  write_index(text);
  ModelStore store(dir_, logged());
  ASSERT_EQ(log_.size(), 1u);
  EXPECT_NE(log_[0].find("damaged"), std::string::npos) << log_[0];
  EXPECT_EQ(store.usage().models, 3u);
  EXPECT_EQ(store.usage().bytes, total_bytes(models_on_disk(dir_)));

  // Not an index at all.
  write_index("models: 3\n");
  log_.clear();
  ModelStore again(dir_, logged());
  ASSERT_EQ(log_.size(), 1u);
  EXPECT_NE(log_[0].find("first line"), std::string::npos) << log_[0];
  EXPECT_EQ(again.usage().models, 3u);
}

TEST_F(StoreIndexFile, AWriteCutShortAtTheEndIsDroppedQuietly) {
  store_three();
  const std::string whole = index_text();
  // A crash in the middle of appending the next record.
  const std::string next = format_record({JournalRecord::Kind::Absent, kA, 0, {}});
  write_index(whole + next.substr(0, next.size() / 2));
  ModelStore store(dir_, logged());
  EXPECT_TRUE(log_.empty()) << log_.front();
  EXPECT_EQ(store.usage().models, 3u);
  EXPECT_EQ(store.usage().bytes, total_bytes(models_on_disk(dir_)));
  EXPECT_EQ(index_text(), whole);
}

TEST_F(StoreIndexFile, AnIndexOfManyMoreRecordsThanModelsIsRewrittenSmall) {
  store_three();
  // Models that came and went, as years of uploads under a bound leave.
  std::string text = index_text();
  for (int i = 0; i < 5000; ++i) {
    char id[33];
    std::snprintf(id, sizeof id, "%032x", i);
    text += format_record({JournalRecord::Kind::Present, id, 2000, {1700000000, i}});
    text += format_record({JournalRecord::Kind::Absent, id, 0, {}});
  }
  write_index(text);
  ModelStore store(dir_, logged());
  EXPECT_TRUE(log_.empty()) << log_.front();
  EXPECT_EQ(store.usage().models, 3u);
  const std::string rewritten = index_text();
  EXPECT_EQ(std::count(rewritten.begin(), rewritten.end(), '\n'), 4) << "header and one record per model";
}

TEST_F(StoreIndexFile, AnotherReplicasRewriteIsReadWhole) {
  ModelStore a(dir_, logged());
  ModelStore b(dir_, logged());
  a.put(padded_model("a"));
  EXPECT_EQ(b.usage().models, 1u);
  // Replica A rewrites the index (as a compaction does): B, still holding
  // the old file open, reads the new one.
  const std::string text = index_text();
  fs::remove(index_path());
  write_index(text + format_record({JournalRecord::Kind::Present, kC, 500, {1, 0}}));
  EXPECT_EQ(b.usage().models, 2u);
  EXPECT_TRUE(log_.empty());
}

// A hung replica holding the store's lock delays an upload by lock_wait,
// then the upload is refused (503 busy): it does not hang with it. Counting
// the store answers from what was last read meanwhile.
TEST_F(StoreIndexFile, ALockHeldPastTheWaitIsBusyNotAHang) {
  StoreOptions options = logged();
  options.lock_wait = std::chrono::milliseconds(200);
  ModelStore store(dir_, options);
  store.put(padded_model("a"));
  const int hung = ::open((dir_ / "models.lock").c_str(), O_RDWR | O_CLOEXEC);
  ASSERT_GE(hung, 0);
  ASSERT_EQ(::flock(hung, LOCK_EX), 0);
  const auto started = std::chrono::steady_clock::now();
  try {
    store.put(padded_model("b"));
    ADD_FAILURE() << "stored while another replica held the lock";
  } catch (const StoreError& e) {
    EXPECT_EQ(e.kind(), StoreError::Kind::Busy);
  }
  EXPECT_GE(std::chrono::steady_clock::now() - started, std::chrono::milliseconds(200));
  EXPECT_EQ(store.usage().models, 1u);
  ::close(hung);
  EXPECT_EQ(store.put(padded_model("b")).created, true);
  EXPECT_EQ(store.usage().models, 2u);
  EXPECT_EQ(models_on_disk(dir_).size(), 2u);
}

// A model removed by hand (not through a store) stays counted until a pass
// of the bound meets it; then it is forgotten, not "let go".
TEST_F(StoreIndexFile, AModelRemovedByHandIsForgottenWhenTheBoundMeetsIt) {
  ModelStore store(dir_, logged(35000));
  const std::string a = store.put(padded_model("a")).info.id;
  const std::string b = store.put(padded_model("b")).info.id;
  store.put(padded_model("c"));
  fs::remove_all(dir_ / "models" / a);
  EXPECT_EQ(store.usage().models, 3u);
  const auto d = store.put(padded_model("d"));
  EXPECT_TRUE(d.evicted.empty()) << d.evicted.front();
  EXPECT_EQ(store.usage().models, 3u);
  EXPECT_EQ(store.usage().bytes, total_bytes(models_on_disk(dir_)));
  EXPECT_EQ(store.evictions(), 0u);
  EXPECT_EQ(store.put(padded_model("e")).evicted, std::vector<std::string>{b});
}

// A render stamps its model's folder, not the index: the bound reads the
// stamp before it lets a model go, so the order is every replica's renders.
TEST_F(StoreIndexFile, ARenderOnAnotherReplicaCountsAsAUseThoughTheIndexDoesNotHaveIt) {
  ModelStore uploading(dir_, logged(35000));
  ModelStore rendering(dir_, logged(35000));
  const std::string a = uploading.put(padded_model("a")).info.id;
  const std::string b = uploading.put(padded_model("b")).info.id;
  uploading.put(padded_model("c"));
  {
    ModelPins pins(rendering);
    pins.add(a);
  }
  EXPECT_EQ(uploading.put(padded_model("d")).evicted, std::vector<std::string>{b});
}

}  // namespace
}  // namespace toond::scene
