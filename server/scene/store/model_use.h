#pragma once
// When a stored model was last used, and whether a render holds it, kept in
// the model's own folder so that every replica sharing the data directory
// reads the same answer:
// - the folder's modification time is its last use, an upload or a render
//   (stamp_use); nothing else writes into the folder once it is stored, so
//   the file system never moves it on its own;
// - `in-use/<holder>`, an empty file, exists while process <holder> has a
//   render of the model queued or running (take_lease, drop_lease). A
//   process that died mid-render leaves its file behind: a lease older than
//   the store's expiry is taken for such a one and ignored.
// Every function here ignores a model folder that has gone meanwhile.
#include <chrono>
#include <ctime>
#include <filesystem>
#include <string>

namespace toond::scene {

inline constexpr const char* kLeaseFolder = "in-use";

// The wall clock, as file times are kept.
std::timespec wall_clock_now();

// Sets the folder's modification time to now (this process's wall clock,
// to the nanosecond, so that two uses in a row keep their order).
void stamp_use(const std::filesystem::path& model_dir);
// The same, with a given time (the one the store's index records).
void stamp_use(const std::filesystem::path& model_dir, const std::timespec& when);

// Creates (or renews) `model_dir/in-use/<holder>`. Best effort: where the
// file cannot be made (a full disk) the render goes on, protected only by
// this process's own pin.
void take_lease(const std::filesystem::path& model_dir, const std::string& holder);
void drop_lease(const std::filesystem::path& model_dir, const std::string& holder);

// Whether any process holds a lease on the model made less than `expiry`
// before `now`.
bool leased(const std::filesystem::path& model_dir, std::chrono::seconds expiry, const std::timespec& now);

}  // namespace toond::scene
