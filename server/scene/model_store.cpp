#include "scene/model_store.h"

#include <cstdio>

#include <fcntl.h>
#include <openssl/evp.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <random>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "scene/bundle_import.h"

namespace toond::scene {
namespace fs = std::filesystem;
namespace {

constexpr std::string_view kTempPrefix = ".tmp-";
constexpr std::size_t kIdLength = 32;

// Ids arrive from URLs: only the exact shape we hand out may touch the disk.
bool valid_id(std::string_view id) {
  return id.size() == kIdLength &&
         std::all_of(id.begin(), id.end(), [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
}

[[noreturn]] void throw_errno(const std::string& what, const fs::path& path) {
  throw std::system_error(errno, std::generic_category(), what + " " + path.string());
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

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path.string());
  std::ostringstream ss;
  ss << in.rdbuf();
  if (!in && !in.eof()) throw std::runtime_error("cannot read " + path.string());
  return ss.str();
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
  nlohmann::json j = {{"id", id},       {"triangles", triangles}, {"materials", materials}, {"textures", textures},
          {"bytes", bytes}, {"files", files},         {"warnings", warnings},
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
      if (const auto rate = c.find("frame_rate"); rate != c.end() && rate->is_number()) clip.frame_rate = rate->get<double>();
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
    feed(std::string_view("\0smooth_angle\0", 14));
    feed(angle);
  }
  if (choices.z_up()) feed(std::string_view("\0up\0z", 6));
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

ModelStore::ModelStore(fs::path data_dir) : root_(std::move(data_dir) / "models") {
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

ModelStore::PutResult ModelStore::put(const Bundle& bundle, const ImportLimits& limits,
                                      const ImportChoices& asked) {
  // The id holds the up axis used, whether asked for or the format's.
  const ImportChoices choices = with_format_up(bundle, asked);
  const std::string id = bundle_id(bundle, choices);
  if (auto existing = info(id)) return {std::move(*existing), false};

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

  const fs::path temp = root_ / (std::string(kTempPrefix) + id + "-" + random_suffix());
  try {
    const fs::path files = temp / "files";
    fs::create_directories(files);
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
    write_file_durably(temp / "info.json",
                       info.to_json().dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
    std::sort(dirs.begin(), dirs.end());
    dirs.erase(std::unique(dirs.begin(), dirs.end()), dirs.end());
    for (const auto& dir : dirs) fsync_dir(dir);

    std::lock_guard lock(mutex_);
    const fs::path final_dir = root_ / id;
    if (fs::exists(final_dir)) {
      // Another upload of the same bundle won the race; its copy is identical.
      remove_quietly(temp);
      auto stored = this->info(id);
      if (stored) return {std::move(*stored), false};
      throw std::runtime_error("model " + id + " is present but unreadable");
    }
    std::error_code ec;
    fs::rename(temp, final_dir, ec);
    if (ec) {
      // Another process sharing the data folder may have stored it first.
      remove_quietly(temp);
      if (auto stored = this->info(id)) return {std::move(*stored), false};
      throw fs::filesystem_error("cannot store model", temp, final_dir, ec);
    }
    fsync_dir(root_);
  } catch (...) {
    remove_quietly(temp);
    throw;
  }
  return {std::move(info), true};
}

std::optional<ModelInfo> ModelStore::info(const std::string& id) const {
  if (!valid_id(id)) return std::nullopt;
  const fs::path path = root_ / id / "info.json";
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return std::nullopt;
  return ModelInfo::from_json(nlohmann::json::parse(read_file(path)));
}

bool ModelStore::contains(const std::string& id) const {
  std::error_code ec;
  return valid_id(id) && fs::is_regular_file(root_ / id / "info.json", ec);
}

std::optional<Bundle> ModelStore::load(const std::string& id) const {
  const auto stored = info(id);
  if (!stored) return std::nullopt;
  const fs::path files = root_ / id / "files";
  Bundle bundle;
  for (const auto& path : stored->files) bundle.add(path, read_file(files / fs::path(path)));
  return bundle;
}

std::vector<ModelInfo> ModelStore::list() const {
  std::vector<ModelInfo> models;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(root_, ec)) {
    const std::string name = entry.path().filename().string();
    if (!valid_id(name)) continue;
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
  if (!valid_id(id)) return false;
  const fs::path doomed = root_ / (std::string(kTempPrefix) + "removed-" + id + "-" + random_suffix());
  {
    std::lock_guard lock(mutex_);
    std::error_code ec;
    fs::rename(root_ / id, doomed, ec);
    if (ec) {
      if (ec == std::errc::no_such_file_or_directory) return false;
      throw fs::filesystem_error("cannot remove model", root_ / id, ec);
    }
    // Once the rename is on disk the model is gone for good, even if the
    // deletion below is interrupted; the next start clears the rest.
    fsync_dir(root_);
  }
  remove_quietly(doomed);
  return true;
}

}  // namespace toond::scene
