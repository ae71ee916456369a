#pragma once
// The store's index on the volume (DATA/models.index), shared by every
// replica: a header line, then one line per change, appended under the
// store's lock (scene/store/store_lock.h) and read by every replica the next
// time it takes the lock. Each line ends in a CRC-32 of itself:
//
//   toond-model-index 1
//   + <id> <bytes> <seconds> <nanoseconds> <crc>   the model is stored
//   - <id> <crc>                                    the model is not
//   ? <id> <bytes> <seconds> <nanoseconds> <crc>   it is about to come or go
//
// An intent ("?") reaches the disk before the model's folder is renamed in
// or out, and is settled by a "+" or "-" once the rename is; one that is
// never settled (its replica died in between) is settled by the next
// replica to take the lock, from what the disk shows. So the file and the
// folders never disagree for long, whatever moment a replica dies in.
//
// A line cut short or garbled at the end of the file is a write a crash
// interrupted, never an intent that took effect (those are synced before
// anything happens): it is dropped. One in the middle means the file is
// damaged. Rewriting the file replaces it whole (a fresh file renamed over
// it), which the other replicas notice and read it again.
#include <cstdint>
#include <ctime>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace toond::scene {

struct JournalRecord {
  enum class Kind : char { Present = '+', Absent = '-', Intent = '?' };
  Kind kind = Kind::Present;
  std::string id;
  std::uint64_t bytes = 0;   // Present and Intent only
  std::timespec last_use{};  // Present and Intent only
};

// One line, newline included.
std::string format_record(const JournalRecord& record);
// One line without its newline; nothing when it is not a whole, intact
// record.
std::optional<JournalRecord> parse_record(std::string_view line);

class StoreJournal {
 public:
  explicit StoreJournal(std::filesystem::path path);
  ~StoreJournal();
  StoreJournal(const StoreJournal&) = delete;
  StoreJournal& operator=(const StoreJournal&) = delete;

  // What was written since the last read, by any replica. Called with the
  // store's lock held.
  struct News {
    enum class State { Intact, Missing, Damaged } state = State::Intact;
    std::string why;  // Damaged: what is wrong, for the log
    // The file was replaced (or read for the first time): `records` is
    // all of it, and what was read before no longer counts.
    bool whole = false;
    std::vector<JournalRecord> records;
  };
  News read();

  // Appends the records, after whatever read() last reached (the store's
  // lock held since). `durably`: on disk before it returns. Throws
  // std::system_error.
  void append(const std::vector<JournalRecord>& records, bool durably);
  // Replaces the file, durably, with one that holds `records` alone.
  void rewrite(const std::vector<JournalRecord>& records);
  // Records in the file: what a rewrite would shrink.
  std::size_t records() const { return records_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  // Reads from offset_ to the end, dropping a torn last line.
  News read_from_offset();
  // Keeps room allocated beyond `end` once little is left.
  void reserve(std::uint64_t end);
  void close();

  std::filesystem::path path_;
  int fd_ = -1;
  std::uint64_t offset_ = 0;  // the end of the last whole record read or written
  std::size_t records_ = 0;
  std::uint64_t reserved_to_ = 0;  // allocated up to here, as far as this replica knows
};

}  // namespace toond::scene
