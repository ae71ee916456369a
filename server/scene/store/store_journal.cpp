#include "scene/store/store_journal.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <charconv>
#include <cstdio>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "scene/store/durable_files.h"
#include "scene/store/store_scan.h"

namespace toond::scene {
namespace fs = std::filesystem;
namespace {

constexpr std::string_view kHeader = "toond-model-index 1\n";
constexpr std::size_t kCrcDigits = 8;
// Room kept allocated past the end of the file (not counted in its size),
// so that the records of a deletion still fit when the volume is full:
// deleting models is how room comes back. About 900 records.
constexpr std::uint64_t kReserve = 64 * 1024;

std::uint32_t crc_of(std::string_view text) {
  return static_cast<std::uint32_t>(
      ::crc32(0L, reinterpret_cast<const Bytef*>(text.data()), static_cast<uInt>(text.size())));
}

bool has_use(JournalRecord::Kind kind) { return kind != JournalRecord::Kind::Absent; }

// Reads an unsigned decimal field up to the next space (or the end);
// moves `text` past it and the space.
template <typename T>
bool take_number(std::string_view& text, T& value) {
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end == text.data()) return false;
  text.remove_prefix(static_cast<std::size_t>(end - text.data()));
  if (text.empty()) return true;
  if (text.front() != ' ') return false;
  text.remove_prefix(1);
  return true;
}

std::optional<JournalRecord> parse_body(std::string_view body) {
  if (body.size() < 2 || body[1] != ' ') return std::nullopt;
  JournalRecord record;
  const char kind = body[0];
  if (kind != '+' && kind != '-' && kind != '?') return std::nullopt;
  record.kind = static_cast<JournalRecord::Kind>(kind);
  body.remove_prefix(2);
  const std::size_t id_end = body.find(' ');
  record.id = std::string(body.substr(0, id_end));
  if (!is_model_id(record.id)) return std::nullopt;
  if (!has_use(record.kind)) return id_end == std::string_view::npos ? std::optional(record) : std::nullopt;
  if (id_end == std::string_view::npos) return std::nullopt;
  body.remove_prefix(id_end + 1);
  long long nanoseconds = 0;
  long long seconds = 0;
  if (!take_number(body, record.bytes) || !take_number(body, seconds) || !take_number(body, nanoseconds) ||
      !body.empty() || nanoseconds < 0 || nanoseconds >= 1000000000) {
    return std::nullopt;
  }
  record.last_use = {static_cast<std::time_t>(seconds), static_cast<long>(nanoseconds)};
  return record;
}

}  // namespace

std::string format_record(const JournalRecord& record) {
  std::string body = std::string(1, static_cast<char>(record.kind)) + " " + record.id;
  if (has_use(record.kind)) {
    body += " " + std::to_string(record.bytes) + " " + std::to_string(record.last_use.tv_sec) + " " +
            std::to_string(record.last_use.tv_nsec);
  }
  char crc[kCrcDigits + 1];
  std::snprintf(crc, sizeof crc, "%08x", crc_of(body));
  return body + " " + crc + "\n";
}

std::optional<JournalRecord> parse_record(std::string_view line) {
  if (line.size() < kCrcDigits + 1 || line[line.size() - kCrcDigits - 1] != ' ') return std::nullopt;
  const std::string_view body = line.substr(0, line.size() - kCrcDigits - 1);
  std::uint32_t crc = 0;
  const std::string_view digits = line.substr(line.size() - kCrcDigits);
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), crc, 16);
  if (error != std::errc() || end != digits.data() + digits.size() || crc != crc_of(body)) return std::nullopt;
  return parse_body(body);
}

StoreJournal::StoreJournal(fs::path path) : path_(std::move(path)) {}

StoreJournal::~StoreJournal() { close(); }

void StoreJournal::close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  offset_ = 0;
  records_ = 0;
  reserved_to_ = 0;
}

StoreJournal::News StoreJournal::read() {
  struct stat on_disk {};
  if (::stat(path_.c_str(), &on_disk) != 0) {
    if (errno != ENOENT) throw_errno("cannot read", path_);
    close();
    return {News::State::Missing, {}, true, {}};
  }
  struct stat open_file {};
  const bool replaced = fd_ < 0 || ::fstat(fd_, &open_file) != 0 || open_file.st_ino != on_disk.st_ino ||
                        open_file.st_dev != on_disk.st_dev;
  if (replaced) {
    close();
    fd_ = ::open(path_.c_str(), O_RDWR | O_CLOEXEC);
    if (fd_ < 0) throw_errno("cannot open", path_);
  }
  News news = read_from_offset();
  news.whole = replaced;
  return news;
}

StoreJournal::News StoreJournal::read_from_offset() {
  struct stat st {};
  if (::fstat(fd_, &st) != 0) throw_errno("cannot read", path_);
  const auto size = static_cast<std::uint64_t>(st.st_size);
  if (size < offset_) return {News::State::Damaged, "it is shorter than when it was last read", false, {}};
  std::string data(size - offset_, '\0');
  for (std::size_t done = 0; done < data.size();) {
    const ssize_t n = ::pread(fd_, data.data() + done, data.size() - done, static_cast<off_t>(offset_ + done));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw_errno("cannot read", path_);
    if (n == 0) {
      data.resize(done);
      break;
    }
    done += static_cast<std::size_t>(n);
  }

  News news;
  std::size_t pos = 0;
  if (offset_ == 0) {
    if (!std::string_view(data).starts_with(kHeader)) {
      return {News::State::Damaged, data.empty() ? "it is empty" : "its first line is not the index's", false, {}};
    }
    pos = kHeader.size();
  }
  std::optional<std::size_t> bad;
  for (std::size_t end; (end = data.find('\n', pos)) != std::string::npos; pos = end + 1) {
    std::optional<JournalRecord> record = parse_record(std::string_view(data).substr(pos, end - pos));
    if (!record) {
      if (!bad) bad = pos;
    } else if (bad) {
      return {
          News::State::Damaged, "the record at byte " + std::to_string(offset_ + *bad) + " is unreadable", false, {}};
    } else {
      news.records.push_back(std::move(*record));
    }
  }
  // What follows the last whole record is a write a crash cut short: no
  // replica holds the lock in the middle of one.
  const std::size_t whole = bad.value_or(pos);
  if (whole < data.size() && ::ftruncate(fd_, static_cast<off_t>(offset_ + whole)) != 0) {
    throw_errno("cannot truncate", path_);
  }
  offset_ += whole;
  records_ += news.records.size();
  return news;
}

void StoreJournal::append(const std::vector<JournalRecord>& records, bool durably) {
  if (fd_ < 0) throw std::logic_error("the store index is appended to before it is read");
  std::string text;
  for (const JournalRecord& record : records) text += format_record(record);
  reserve(offset_ + text.size());
  try {
    write_all_at(fd_, text, offset_, path_);
  } catch (...) {
    // A part written is dropped now, or as a torn line by the next read.
    [[maybe_unused]] const int ignored = ::ftruncate(fd_, static_cast<off_t>(offset_));
    throw;
  }
  offset_ += text.size();
  records_ += records.size();
  if (durably && ::fdatasync(fd_) != 0) throw_errno("cannot sync", path_);
}

void StoreJournal::rewrite(const std::vector<JournalRecord>& records) {
  // Under the store's lock no other replica writes this name.
  const fs::path fresh = path_.string() + ".new";
  std::string text(kHeader);
  for (const JournalRecord& record : records) text += format_record(record);
  {
    Fd fd(::open(fresh.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644));
    if (fd.get() < 0) throw_errno("cannot create", fresh);
    write_all_at(fd.get(), text, 0, fresh);
    if (::fsync(fd.get()) != 0) throw_errno("cannot sync", fresh);
  }
  if (::rename(fresh.c_str(), path_.c_str()) != 0) throw_errno("cannot replace", path_);
  fsync_dir(path_.parent_path());
  close();
  fd_ = ::open(path_.c_str(), O_RDWR | O_CLOEXEC);
  if (fd_ < 0) throw_errno("cannot open", path_);
  offset_ = text.size();
  records_ = records.size();
  reserve(offset_);
}

void StoreJournal::reserve(std::uint64_t end) {
  if (end + kReserve / 2 <= reserved_to_) return;
  // Best effort: a file system without fallocate() (some NFS servers) keeps
  // no reserve, and a full volume then refuses a deletion's records too.
  if (::fallocate(fd_, FALLOC_FL_KEEP_SIZE, static_cast<off_t>(end), static_cast<off_t>(kReserve)) == 0) {
    reserved_to_ = end + kReserve;
  }
}

}  // namespace toond::scene
