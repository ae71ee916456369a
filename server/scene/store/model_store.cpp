#include "scene/store/model_store.h"

#include <fcntl.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <iostream>
#include <random>
#include <sstream>
#include <system_error>
#include <utility>

#include "scene/import/bundle_import.h"
#include "scene/store/durable_files.h"
#include "scene/store/model_use.h"

namespace toond::scene {
namespace fs = std::filesystem;
namespace {

constexpr std::string_view kTempPrefix = ".tmp-";

StoreError larger_than_store(std::uint64_t bytes, std::uint64_t max_bytes) {
  return StoreError(StoreError::Kind::LargerThanStore, "the model takes " + std::to_string(bytes) +
                                                           " bytes, more than the whole store may hold (" +
                                                           std::to_string(max_bytes) + " bytes)");
}

// A stored file's bytes; nothing when it is not there (its model was let
// go or removed meanwhile). Any other failure is a StoreError.
std::optional<std::string> read_stored_file(const fs::path& path) {
  Fd fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
  try {
    if (fd.get() < 0) {
      if (errno == ENOENT || errno == ENOTDIR) return std::nullopt;
      throw_errno("cannot open", path);
    }
    std::string bytes;
    char buffer[1 << 16];
    while (true) {
      const ssize_t n = ::read(fd.get(), buffer, sizeof buffer);
      if (n < 0) {
        if (errno == EINTR) continue;
        throw_errno("cannot read", path);
      }
      if (n == 0) return bytes;
      bytes.append(buffer, static_cast<std::size_t>(n));
    }
  } catch (const std::system_error& e) {
    throw_store_failure(e, "a stored model could not be read");
  }
}

std::string random_suffix() {
  // Seeded once per thread: opening the random device for every name cost
  // more than the rename the name is for.
  thread_local std::mt19937_64 random = [] {
    std::random_device device;
    std::seed_seq seed{device(), device(), device(), static_cast<unsigned>(::getpid())};
    return std::mt19937_64(seed);
  }();
  std::ostringstream ss;
  ss << std::hex << random();
  return ss.str();
}

// Removing a folder that a crash left half-deleted must not stop the store.
void remove_quietly(const fs::path& path) {
  std::error_code ec;
  fs::remove_all(path, ec);
}

// Creates DIR/models when needed and clears what interrupted uploads and
// deletions left there long enough ago.
fs::path open_root(const fs::path& root) {
  fs::create_directories(root);
  const auto stale_before = fs::file_time_type::clock::now() - ModelStore::kStaleTempAge;
  for (const auto& entry : fs::directory_iterator(root)) {
    if (!entry.path().filename().string().starts_with(kTempPrefix)) continue;
    std::error_code ec;
    const auto written = fs::last_write_time(entry.path(), ec);
    if (!ec && written < stale_before) remove_quietly(entry.path());
  }
  fsync_dir(root);
  return root;
}

StoreCatalog::Log log_or_stderr(std::function<void(const std::string&)> log) {
  if (log) return log;
  return [](const std::string& line) { std::cerr << "toond: " << line << "\n"; };
}

}  // namespace

ModelStore::ModelStore(fs::path data_dir, StoreOptions options)
    : root_(data_dir / "models"),
      options_(std::move(options)),
      holder_(std::to_string(::getpid()) + "-" + random_suffix()),
      catalog_(open_root(root_), options_.lock_wait, log_or_stderr(options_.log)) {}

ModelStore::PutResult ModelStore::put(const Bundle& bundle, const ImportLimits& limits, const ImportChoices& asked) {
  // The id holds the up axis used, whether asked for or the format's.
  const ImportChoices choices = with_format_up(bundle, asked);
  const std::string id = bundle_id(bundle, choices);
  if (auto existing = info(id)) {
    stamp_use(root_ / id);
    return {std::move(*existing), false, {}};
  }

  const bool bounded = options_.max_bytes > 0;
  // Larger than the bound before it is even imported: refused at once.
  if (bounded && bundle.total_bytes() > options_.max_bytes) {
    throw larger_than_store(bundle.total_bytes(), options_.max_bytes);
  }

  // The import runs unlocked: it can take a while (texture decoding) and
  // concerns only this bundle.
  const Model model = import_bundle(bundle, limits, choices);
  ModelInfo info;
  info.id = id;
  info.choices = choices;
  info.triangles = model.mesh.triangle_count();
  info.materials = model.materials.size();
  info.textures = model.textures.size();
  info.material_list = material_entries(model);
  info.bytes = bundle.total_bytes();
  for (const auto& [path, content] : bundle.files()) info.files.push_back(path);
  info.warnings = model.warnings;
  info.weld = {model.mesh.weld_tolerance, model.mesh.welded_positions};
  info.cost = {model.mesh.cost.layers(), model.mesh.cost.edge_span()};
  if (model.rig) {
    for (const Clip& clip : model.rig->clips) {
      info.animation.clips.push_back({clip.name, clip.duration, clip.channels.size(), clip.frame_rate});
    }
    info.animation.joints = model.rig->joint_count;
    info.animation.morph_targets = model.rig->morph_target_count;
  }
  const std::string info_text = info.to_json().dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
  const std::uint64_t bytes = info.bytes + info_text.size();
  if (bounded && bytes > options_.max_bytes) throw larger_than_store(bytes, options_.max_bytes);

  // Written unlocked too; only the rename into place waits for the lock.
  const fs::path temp = write_temp(id, bundle, info_text);
  try {
    return land(temp, std::move(info), bytes);
  } catch (...) {
    remove_quietly(temp);
    throw;
  }
}

ModelStore::PutResult ModelStore::land(const fs::path& temp, ModelInfo info, std::uint64_t bytes) {
  const std::string id = info.id;
  PutResult result{std::move(info), true, {}};
  std::vector<fs::path> doomed;
  const auto delete_doomed = [&] {
    for (fs::path& folder : doomed) sweeper_.sweep(std::move(folder));
  };
  try {
    StoreCatalog::Pass pass = catalog_.pass();
    if (contains(id)) {
      // Another upload of the same bundle got there first; its copy is
      // identical.
      remove_quietly(temp);
      stamp_use(root_ / id);
      auto stored = this->info(id);
      if (!stored) throw StoreError(StoreError::Kind::Failed, "model " + id + " is present but unreadable");
      return {std::move(*stored), false, {}};
    }
    const std::timespec now = wall_clock_now();
    std::vector<JournalRecord> intents{{JournalRecord::Kind::Intent, id, bytes, now}};
    // Usually one round; another only when a render took a chosen model
    // before it could go.
    while (options_.max_bytes > 0) {
      const Choice choice = choose(pass, bytes);
      if (choice.refused) {
        throw StoreError(StoreError::Kind::FullOfModelsInUse,
                         "the store is at its bound and renders hold every model that could make room for this one");
      }
      if (choice.models.empty()) break;
      intents.insert(intents.end(), choice.models.begin(), choice.models.end());
      pass.intend(intents);
      intents.clear();
      checkpoint("intended");
      let_go(pass, choice, doomed, result.evicted);
    }
    if (!intents.empty()) pass.intend(intents);
    try {
      stamp_use(temp, now);
      fs::rename(temp, root_ / id);
    } catch (const std::system_error& e) {
      throw_store_failure(e, "the model could not be stored");
    }
    checkpoint("renamed");
    pass.settle();
  } catch (...) {
    delete_doomed();
    throw;
  }
  delete_doomed();
  return result;
}

ModelStore::Choice ModelStore::choose(StoreCatalog::Pass& pass, std::uint64_t incoming) {
  const std::uint64_t max = options_.max_bytes;
  const StoreIndex& index = pass.index();
  Choice choice;
  std::uint64_t freed = 0;
  const auto over = [&] { return index.usage().bytes - freed + incoming > max; };
  if (!over()) return choice;
  std::lock_guard lock(pins_mutex_);
  for (auto it = index.order().begin(); it != index.order().end() && over();) {
    const std::string id = it->id;
    const auto next = std::next(it);
    const std::optional<std::timespec> used = last_use(root_ / id);
    if (!used) {
      // Gone, by no pass of the store's (removed by hand).
      pass.forget(id);
      it = next;
      continue;
    }
    if (StoreIndex::Key{it->last_use, id} < StoreIndex::Key{*used, id}) {
      // Used since the index last looked: its place is further on, maybe
      // still before the next one's.
      const auto moved = pass.restamp(id, *used);
      it = next == index.order().end() || *moved < *next ? moved : next;
      continue;
    }
    if (!held(id)) {
      const std::uint64_t bytes = index.bytes(id);
      choice.models.push_back({JournalRecord::Kind::Intent, id, bytes, *used});
      freed += bytes;
    }
    it = next;
  }
  if (over()) return {true, {}};
  return choice;
}

void ModelStore::let_go(StoreCatalog::Pass& pass, const Choice& choice, std::vector<fs::path>& doomed,
                        std::vector<std::string>& evicted) {
  // Under the pins' lock: a render of this process that pins a model now
  // either comes first (and keeps it) or finds it gone.
  std::lock_guard lock(pins_mutex_);
  for (const JournalRecord& model : choice.models) {
    if (held(model.id)) continue;
    std::optional<fs::path> out = take_out(model.id);
    if (!out) continue;
    pass.left(model.id);
    doomed.push_back(std::move(*out));
    evicted.push_back(model.id);
    ++evictions_;
    checkpoint("evicting");
  }
}

fs::path ModelStore::write_temp(const std::string& id, const Bundle& bundle, const std::string& info_text) {
  const fs::path temp = root_ / (std::string(kTempPrefix) + id + "-" + random_suffix());
  try {
    const fs::path files = temp / "files";
    fs::create_directories(files);
    fs::create_directory(temp / kLeaseFolder);
    std::vector<fs::path> dirs{temp, files};
    for (const auto& [path, content] : bundle.files()) {
      const fs::path target = files / fs::path(path);
      if (target.parent_path() != files && !fs::exists(target.parent_path())) {
        // Every new folder must reach the disk too, not only its files.
        for (fs::path dir = target.parent_path(); dir != files; dir = dir.parent_path()) dirs.push_back(dir);
        fs::create_directories(target.parent_path());
      }
      write_file_durably(target, content);
    }
    write_file_durably(temp / "info.json", info_text);
    std::sort(dirs.begin(), dirs.end());
    dirs.erase(std::unique(dirs.begin(), dirs.end()), dirs.end());
    for (const auto& dir : dirs) fsync_dir(dir);
  } catch (const std::system_error& e) {
    remove_quietly(temp);
    throw_store_failure(e, "the model could not be stored");
  } catch (...) {
    remove_quietly(temp);
    throw;
  }
  return temp;
}

std::optional<ModelInfo> ModelStore::info(const std::string& id) const {
  if (!is_model_id(id)) return std::nullopt;
  const std::optional<std::string> text = read_stored_file(root_ / id / "info.json");
  if (!text) return std::nullopt;
  return ModelInfo::from_json(nlohmann::json::parse(*text));
}

bool ModelStore::contains(const std::string& id) const {
  std::error_code ec;
  return is_model_id(id) && fs::is_regular_file(root_ / id / "info.json", ec);
}

std::optional<Bundle> ModelStore::load(const std::string& id) const {
  const auto stored = info(id);
  if (!stored) return std::nullopt;
  const fs::path files = root_ / id / "files";
  Bundle bundle;
  for (const auto& path : stored->files) {
    std::optional<std::string> bytes = read_stored_file(files / fs::path(path));
    if (!bytes) {
      if (!contains(id)) return std::nullopt;
      throw StoreError(StoreError::Kind::Failed, "stored model " + id + " is damaged: its file " + path + " is missing",
                       (files / fs::path(path)).string() + " is missing");
    }
    bundle.add(path, std::move(*bytes));
  }
  return bundle;
}

std::vector<ModelInfo> ModelStore::list() const {
  std::vector<ModelInfo> models;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(root_, ec)) {
    const std::string name = entry.path().filename().string();
    if (!is_model_id(name)) continue;
    // A model removed between listing and reading is simply not listed.
    try {
      if (auto stored = info(name)) models.push_back(std::move(*stored));
    } catch (const std::exception&) {
    }
  }
  std::sort(models.begin(), models.end(), [](const ModelInfo& a, const ModelInfo& b) { return a.id < b.id; });
  return models;
}

bool ModelStore::remove(const std::string& id) {
  if (!contains(id)) return false;
  std::optional<fs::path> doomed;
  {
    StoreCatalog::Pass pass = catalog_.pass();
    pass.intend({{JournalRecord::Kind::Intent, id, pass.index().bytes(id), {}}});
    doomed = take_out(id);
    if (doomed) pass.left(id);
    pass.settle();
  }
  if (!doomed) return false;
  remove_quietly(*doomed);
  return true;
}

std::optional<fs::path> ModelStore::take_out(const std::string& id) {
  const fs::path doomed = root_ / (std::string(kTempPrefix) + "removed-" + id + "-" + random_suffix());
  if (::rename((root_ / id).c_str(), doomed.c_str()) == 0) return doomed;
  const int error = errno;
  if (error == ENOENT) return std::nullopt;
  throw_store_failure(std::system_error(error, std::generic_category(), "cannot remove model " + (root_ / id).string()),
                      "the model could not be removed");
}

void ModelStore::pin(const std::string& id) {
  if (!is_model_id(id)) return;
  {
    std::lock_guard lock(pins_mutex_);
    ++pins_[id];
  }
  stamp_use(root_ / id);
}

void ModelStore::unpin(const std::string& id) {
  std::lock_guard lock(pins_mutex_);
  const auto it = pins_.find(id);
  if (it != pins_.end() && --it->second == 0) pins_.erase(it);
}

void ModelStore::lease(const std::string& id) {
  if (!is_model_id(id)) return;
  std::lock_guard lock(pins_mutex_);
  if (leases_[id]++ == 0) take_lease(root_ / id, holder_);
}

void ModelStore::unlease(const std::string& id) {
  std::lock_guard lock(pins_mutex_);
  const auto it = leases_.find(id);
  if (it == leases_.end() || --it->second > 0) return;
  leases_.erase(it);
  drop_lease(root_ / id, holder_);
}

bool ModelStore::held(const std::string& id) const {
  return pins_.count(id) > 0 || leased(root_ / id, options_.lease_expiry, wall_clock_now());
}

void ModelStore::checkpoint(std::string_view moment) const {
  if (options_.checkpoint) options_.checkpoint(moment);
}

StoreUsage ModelStore::usage() const { return catalog_.usage(); }

std::optional<ModelStore::Volume> ModelStore::volume() const {
  struct statvfs st {};
  if (::statvfs(root_.c_str(), &st) != 0) return std::nullopt;
  return Volume{static_cast<std::uint64_t>(st.f_blocks) * st.f_frsize,
                static_cast<std::uint64_t>(st.f_bavail) * st.f_frsize};
}

}  // namespace toond::scene
