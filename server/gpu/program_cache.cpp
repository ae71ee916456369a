#include "gpu/program_cache.h"

#include <algorithm>
#include <set>

#include "gpu/shader_compile_error.h"
#include "gpu/shader_includes.h"

namespace toond::gpu {

ProgramCache::ProgramCache(SourceLookup lookup) : sources_(std::make_unique<FixedShaderSources>(std::move(lookup))) {}

ProgramCache::ProgramCache(std::unique_ptr<ShaderSources> sources) : sources_(std::move(sources)) {}

const std::string& ProgramCache::text(const std::string& name) {
  auto it = live_.find(name);
  if (it != live_.end()) return it->second;
  std::string source = sources_->read(name);  // throws: nothing is remembered
  if (sources_->can_change()) disk_[name] = DiskText{source, nullptr};
  return live_.emplace(name, std::move(source)).first->second;
}

Program& ProgramCache::get(const std::string& vertex, const std::string& fragment, std::vector<std::string> defines) {
  return get(std::vector<std::string>{vertex, fragment}, std::move(defines));
}

Program& ProgramCache::get(const std::vector<std::string>& stages, std::vector<std::string> defines) {
  std::sort(defines.begin(), defines.end());
  std::string key;
  for (const auto& file : stages) key += file + "|";
  for (const auto& d : defines) key += "|" + d;
  auto it = programs_.find(key);
  if (it != programs_.end()) return *it->second.program;
  Built built = build(stages, defines, [&](const std::string& name) { return text(name); });
  Entry entry{stages, std::move(built.files), std::move(defines), std::move(built.program)};
  return *programs_.emplace(key, std::move(entry)).first->second.program;
}

ProgramCache::Built ProgramCache::build(const std::vector<std::string>& stages, const std::vector<std::string>& defines,
                                        const ShaderTextReader& read) {
  Built built;
  std::vector<ShaderSource> sources;
  for (const auto& file : stages) {
    ExpandedShader expanded = expand_includes(file, read);
    for (const std::string& used : expanded.files) {
      if (std::find(built.files.begin(), built.files.end(), used) == built.files.end()) built.files.push_back(used);
    }
    sources.push_back({file, std::move(expanded.text), std::move(expanded.files)});
  }
  built.program = std::make_unique<Program>(sources, defines);
  return built;
}

ProgramCache::Reload ProgramCache::refresh() {
  if (!sources_->can_change()) return {};
  const std::vector<std::string> changed = sources_->changed();
  if (changed.empty()) return {};

  for (const auto& name : changed) {
    // Reading records what was seen, so an edit is looked at once.
    DiskText latest;
    try {
      latest.text = sources_->read(name);
    } catch (const GpuError&) {
      latest.error = std::current_exception();
    }
    // A file no cached program was built from is read again when needed.
    if (live_.contains(name)) disk_[name] = std::move(latest);
  }

  // Every file whose latest text is not the live one: edits made since the
  // last good state, including ones that did not compile then.
  std::set<std::string> stale;
  for (const auto& [name, latest] : disk_) {
    if (latest.error) std::rethrow_exception(latest.error);
    if (latest.text != live_.at(name)) stale.insert(name);
  }
  if (stale.empty()) return {};

  // Build every affected variant before swapping any in: the cache never
  // mixes old and new texts, and a failure leaves it untouched. An edit may
  // include a module no program used yet: it is read here and kept only if
  // everything builds.
  std::map<std::string, std::string> first_read;
  auto text_of = [&](const std::string& name) -> std::string {
    if (stale.contains(name)) return disk_.at(name).text;
    if (auto live = live_.find(name); live != live_.end()) return live->second;
    if (auto read = first_read.find(name); read != first_read.end()) return read->second;
    return first_read.emplace(name, sources_->read(name)).first->second;
  };
  std::vector<std::pair<Entry*, Built>> rebuilt;
  for (auto& [key, entry] : programs_) {
    const bool affected = std::any_of(entry.files.begin(), entry.files.end(),
                                      [&](const std::string& file) { return stale.contains(file); });
    if (!affected) continue;
    rebuilt.emplace_back(&entry, build(entry.stages, entry.defines, text_of));
  }

  Reload reload;
  for (auto& [entry, built] : rebuilt) {
    entry->program = std::move(built.program);
    entry->files = std::move(built.files);
  }
  for (const auto& name : stale) {
    live_[name] = disk_.at(name).text;
    reload.files.push_back(name);
  }
  for (auto& [name, text] : first_read) {
    disk_[name] = DiskText{text, nullptr};
    live_[name] = std::move(text);
  }
  reload.programs = rebuilt.size();
  return reload;
}

void ProgramCache::clear() {
  programs_.clear();
  live_.clear();
  disk_.clear();
}

}  // namespace toond::gpu
