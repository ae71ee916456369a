#include "scene/store/model_store.h"

#include <cstdio>

#include <fcntl.h>
#include <openssl/evp.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <memory>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "scene/import/bundle_import.h"
#include "scene/store/model_use.h"

namespace toond::scene {
namespace fs = std::filesystem;
using namespace std::string_view_literals;
namespace {

constexpr std::string_view kTempPrefix = ".tmp-";
constexpr std::size_t kIdLength = 32;

[[noreturn]] void throw_errno(const std::string& what, const fs::path& path) {
  throw std::system_error(errno, std::generic_category(), what + " " + path.string());
}

bool volume_full(const std::error_code& code) {
  const std::error_condition condition = code.default_error_condition();
  return condition == std::errc::no_space_on_device ||
         condition == std::error_condition(EDQUOT, std::generic_category());
}

// An I/O failure as a client may read it: what could not be done and the
// system's reason, never a server path; the whole text goes to the log.
[[noreturn]] void throw_store_failure(const std::system_error& e, const std::string& what_failed) {
  if (volume_full(e.code())) {
    throw StoreError(StoreError::Kind::VolumeFull,
                     "the volume the models are stored on is full (" + e.code().message() + ")", e.what());
  }
  throw StoreError(StoreError::Kind::Failed, what_failed + " (" + e.code().message() + ")", e.what());
}

class Fd {
 public:
  explicit Fd(int fd) : fd_(fd) {}
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd() {
    if (fd_ >= 0) ::close(fd_);
  }
  int get() const { return fd_; }
  int release() { return std::exchange(fd_, -1); }

 private:
  int fd_;
};

void fsync_dir(const fs::path& dir) {
  Fd fd(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (fd.get() < 0) throw_errno("cannot open folder", dir);
  if (::fsync(fd.get()) != 0) throw_errno("cannot sync folder", dir);
}

void write_file_durably(const fs::path& path, std::string_view bytes) {
  Fd fd(::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644));
  if (fd.get() < 0) throw_errno("cannot create", path);
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd.get(), bytes.data() + done, bytes.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw_errno("cannot write", path);
    }
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd.get()) != 0) throw_errno("cannot sync", path);
  if (::close(fd.release()) != 0) throw_errno("cannot close", path);
}

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
  static std::atomic<std::uint64_t> counter{0};
  std::random_device device;
  const std::uint64_t value = (static_cast<std::uint64_t>(device()) << 32) ^ device() ^ (counter++ << 48) ^
                              static_cast<std::uint64_t>(::getpid());
  std::ostringstream ss;
  ss << std::hex << value;
  return ss.str();
}

// Removing a folder that a crash left half-deleted must not stop the store.
void remove_quietly(const fs::path& path) {
  std::error_code ec;
  fs::remove_all(path, ec);
}

// The up axis a stored model was imported with. Models stored before the
// format's convention was the default say "up" only when it was `z`;
// without it they were read Y-up, but for 3MF, which the assimp helper then
// turned itself.
ImportChoices::Up stored_up(const nlohmann::json& j, const std::vector<std::string>& files) {
  if (const auto up = j.find("up"); up != j.end() && up->is_string()) {
    return *up == "z" ? ImportChoices::Up::Z : ImportChoices::Up::Y;
  }
  const bool three_mf =
      std::any_of(files.begin(), files.end(), [](const std::string& file) { return has_extension(file, ".3mf"); });
  return three_mf ? ImportChoices::Up::Z : ImportChoices::Up::Y;
}

}  // namespace

nlohmann::json ModelInfo::to_json() const {
  nlohmann::json j = {{"id", id},
                      {"triangles", triangles},
                      {"materials", materials},
                      {"textures", textures},
                      {"bytes", bytes},
                      {"files", files},
                      {"warnings", warnings},
                      {"weld", {{"tolerance", weld.tolerance}, {"positions", weld.positions}}},
                      {"cost", {{"layers", cost.layers}, {"edge_span", cost.edge_span}}}};
  if (animation.any()) {
    nlohmann::json clips = nlohmann::json::array();
    for (const ClipInfo& c : animation.clips) {
      nlohmann::json clip = {{"name", c.name}, {"duration", c.duration}, {"channels", c.channels}};
      if (c.frame_rate) clip["frame_rate"] = *c.frame_rate;
      clips.push_back(std::move(clip));
    }
    j["animation"] = {{"clips", clips}, {"joints", animation.joints}, {"morph_targets", animation.morph_targets}};
  }
  if (choices.gltf_scene) j["scene"] = *choices.gltf_scene;
  if (choices.smooth_angle) j["smooth_angle"] = *choices.smooth_angle;
  if (choices.up != ImportChoices::Up::FormatDefault) j["up"] = choices.z_up() ? "z" : "y";
  return j;
}

ModelInfo ModelInfo::from_json(const nlohmann::json& j) {
  ModelInfo info;
  info.id = j.at("id").get<std::string>();
  info.triangles = j.at("triangles").get<std::size_t>();
  info.materials = j.at("materials").get<std::size_t>();
  info.textures = j.at("textures").get<std::size_t>();
  info.bytes = j.at("bytes").get<std::size_t>();
  info.files = j.at("files").get<std::vector<std::string>>();
  info.warnings = j.value("warnings", std::vector<std::string>{});
  // Models stored before their cost was measured have no record of it.
  if (const auto cost = j.find("cost"); cost != j.end() && cost->is_object()) {
    info.cost.layers = cost->value("layers", 0.0);
    info.cost.edge_span = cost->value("edge_span", 0.0);
  }
  // Models stored before welding was reported have no record of it.
  if (const auto weld = j.find("weld"); weld != j.end() && weld->is_object()) {
    info.weld.tolerance = weld->value("tolerance", 0.0);
    info.weld.positions = weld->value("positions", std::size_t{0});
  }
  if (const auto animation = j.find("animation"); animation != j.end() && animation->is_object()) {
    for (const nlohmann::json& c : animation->value("clips", nlohmann::json::array())) {
      ClipInfo clip{c.value("name", std::string()), c.value("duration", 0.0), c.value("channels", std::size_t{0}), {}};
      if (const auto rate = c.find("frame_rate"); rate != c.end() && rate->is_number())
        clip.frame_rate = rate->get<double>();
      info.animation.clips.push_back(std::move(clip));
    }
    info.animation.joints = animation->value("joints", std::size_t{0});
    info.animation.morph_targets = animation->value("morph_targets", std::size_t{0});
  }
  if (const auto scene = j.find("scene"); scene != j.end() && scene->is_number_integer()) {
    info.choices.gltf_scene = scene->get<int>();
  }
  if (const auto angle = j.find("smooth_angle"); angle != j.end() && angle->is_number()) {
    info.choices.smooth_angle = angle->get<double>();
  }
  info.choices.up = stored_up(j, info.files);
  return info;
}

std::string bundle_id(const Bundle& bundle, const ImportChoices& choices) {
  std::unique_ptr<EVP_MD_CTX, void (*)(EVP_MD_CTX*)> ctx(EVP_MD_CTX_new(), EVP_MD_CTX_free);
  if (!ctx || EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr) != 1) {
    throw std::runtime_error("SHA-256 is not available");
  }
  const auto feed = [&](std::string_view bytes) {
    if (EVP_DigestUpdate(ctx.get(), bytes.data(), bytes.size()) != 1) throw std::runtime_error("SHA-256 failed");
  };
  // Sizes and separators keep the records unambiguous: no two different
  // bundles produce the same byte stream.
  for (const auto& [path, content] : bundle.files()) {
    feed(path);
    feed(std::string_view("\0", 1));
    feed(std::to_string(content.size()));
    feed(std::string_view("\0", 1));
    feed(content);
  }
  // No path holds a NUL, so this record cannot be taken for a file's.
  if (choices.gltf_scene) {
    feed(std::string_view("\0scene\0", 7));
    feed(std::to_string(*choices.gltf_scene));
  }
  if (choices.smooth_angle) {
    char angle[32];
    std::snprintf(angle, sizeof angle, "%.17g", *choices.smooth_angle);
    feed("\0smooth_angle\0"sv);
    feed(angle);
  }
  if (choices.z_up()) feed("\0up\0z"sv);
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  if (EVP_DigestFinal_ex(ctx.get(), digest, &length) != 1) throw std::runtime_error("SHA-256 failed");
  static constexpr char kHex[] = "0123456789abcdef";
  std::string id;
  for (unsigned int i = 0; i < length && id.size() < kIdLength; ++i) {
    id += kHex[digest[i] >> 4];
    id += kHex[digest[i] & 0xf];
  }
  return id;
}

ModelStore::ModelStore(fs::path data_dir, StoreOptions options)
    : root_(data_dir / "models"), options_(options), holder_(std::to_string(::getpid()) + "-" + random_suffix()) {
  fs::create_directories(root_);
  const auto stale_before = fs::file_time_type::clock::now() - kStaleTempAge;
  for (const auto& entry : fs::directory_iterator(root_)) {
    if (!entry.path().filename().string().starts_with(kTempPrefix)) continue;
    std::error_code ec;
    const auto written = fs::last_write_time(entry.path(), ec);
    if (!ec && written < stale_before) remove_quietly(entry.path());
  }
  fsync_dir(root_);
}

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

  PutResult result{std::move(info), true, {}};
  if (bounded) {
    if (bytes > options_.max_bytes) throw larger_than_store(bytes, options_.max_bytes);
    std::lock_guard lock(evict_mutex_);
    Room room = make_room(bytes, id, true);
    result.evicted = std::move(room.evicted);
    if (room.refused) {
      throw StoreError(StoreError::Kind::FullOfModelsInUse,
                       "the store is at its bound and renders hold every model that could make room for this one");
    }
    auto& [writers, reserved_bytes] = reserved_[id];
    ++writers;
    reserved_bytes = bytes;
  }
  const auto release = [&] {
    if (!bounded) return;
    std::lock_guard lock(evict_mutex_);
    if (--reserved_[id].first == 0) reserved_.erase(id);
  };
  bool written = false;
  try {
    written = write_model(id, bundle, info_text);
  } catch (...) {
    release();
    throw;
  }
  release();
  if (!written) {
    // Another upload of the same bundle won the race; its copy is identical.
    auto stored = this->info(id);
    if (!stored) throw StoreError(StoreError::Kind::Failed, "model " + id + " is present but unreadable");
    return {std::move(*stored), false, std::move(result.evicted)};
  }
  stamp_use(root_ / id);
  if (bounded) {
    // Other replicas' uploads may have landed meanwhile: back under the
    // bound, this model spared.
    std::lock_guard lock(evict_mutex_);
    Room room = make_room(0, id, false);
    result.evicted.insert(result.evicted.end(), room.evicted.begin(), room.evicted.end());
  }
  return result;
}

bool ModelStore::write_model(const std::string& id, const Bundle& bundle, const std::string& info_text) {
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

    std::lock_guard lock(mutex_);
    const fs::path final_dir = root_ / id;
    if (fs::exists(final_dir)) {
      remove_quietly(temp);
      return false;
    }
    std::error_code ec;
    fs::rename(temp, final_dir, ec);
    if (ec) {
      // Another process sharing the data folder may have stored it first.
      remove_quietly(temp);
      if (contains(id)) return false;
      throw fs::filesystem_error("cannot store model", temp, final_dir, ec);
    }
    fsync_dir(root_);
  } catch (const std::system_error& e) {
    remove_quietly(temp);
    throw_store_failure(e, "the model could not be stored");
  } catch (...) {
    remove_quietly(temp);
    throw;
  }
  return true;
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
  if (!is_model_id(id)) return false;
  std::optional<fs::path> doomed;
  {
    std::lock_guard lock(mutex_);
    doomed = take_out(id);
  }
  if (!doomed) return false;
  remove_quietly(*doomed);
  return true;
}

std::optional<fs::path> ModelStore::take_out(const std::string& id) {
  const fs::path doomed = root_ / (std::string(kTempPrefix) + "removed-" + id + "-" + random_suffix());
  try {
    std::error_code ec;
    fs::rename(root_ / id, doomed, ec);
    if (ec) {
      if (ec == std::errc::no_such_file_or_directory) return std::nullopt;
      throw fs::filesystem_error("cannot remove model", root_ / id, ec);
    }
    // Once the rename is on disk the model is gone for good, even if the
    // deletion that follows is interrupted; the next start clears the rest.
    fsync_dir(root_);
  } catch (const std::system_error& e) {
    throw_store_failure(e, "the model could not be removed");
  }
  sizes_.forget(id);
  return doomed;
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

ModelStore::Letting ModelStore::evict(const std::string& id) {
  std::optional<fs::path> doomed;
  {
    // Under the pins' lock: a render of this process that pins the model
    // now either comes first (and keeps it) or finds it gone.
    std::lock_guard lock(pins_mutex_);
    if (held(id)) return Letting::Held;
    doomed = take_out(id);
  }
  if (!doomed) return Letting::Gone;
  remove_quietly(*doomed);
  ++evictions_;
  return Letting::Evicted;
}

ModelStore::Room ModelStore::make_room(std::uint64_t incoming, const std::string& spare, bool refuse_when_held) {
  const std::vector<StoredModel> models = sizes_.scan(root_);
  std::uint64_t kept = add_up(models).bytes;
  for (const auto& held : reserved_) {
    const std::string& id = held.first;
    const bool in_place = std::any_of(models.begin(), models.end(), [&](const StoredModel& m) { return m.id == id; });
    if (!in_place) kept += held.second.second;
  }
  const std::uint64_t max = options_.max_bytes;
  Room room;
  if (kept + incoming <= max) return room;
  // The least recently used that no render holds, as many as it takes; and
  // what the held ones take, which no eviction can free.
  std::vector<const StoredModel*> chosen;
  std::uint64_t freed = 0;
  std::uint64_t held_bytes = 0;
  {
    std::lock_guard lock(pins_mutex_);
    for (const StoredModel& m : models) {
      if (m.id == spare) continue;
      if (held(m.id)) {
        held_bytes += m.bytes;
      } else if (kept - freed + incoming > max) {
        chosen.push_back(&m);
        freed += m.bytes;
      }
    }
  }
  // Uploads this process is still writing do not make a refusal: they
  // land, and the oldest of them goes in its turn.
  if (refuse_when_held && held_bytes + incoming > max) {
    room.refused = true;
    return room;
  }
  for (const StoredModel* m : chosen) {
    const Letting letting = evict(m->id);
    if (letting == Letting::Held) continue;  // a render took it meanwhile
    if (letting == Letting::Evicted) room.evicted.push_back(m->id);
  }
  return room;
}

StoreUsage ModelStore::usage() const { return add_up(sizes_.scan(root_)); }

std::optional<ModelStore::Volume> ModelStore::volume() const {
  struct statvfs st {};
  if (::statvfs(root_.c_str(), &st) != 0) return std::nullopt;
  return Volume{static_cast<std::uint64_t>(st.f_blocks) * st.f_frsize,
                static_cast<std::uint64_t>(st.f_bavail) * st.f_frsize};
}

}  // namespace toond::scene
