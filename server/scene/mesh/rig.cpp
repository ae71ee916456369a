#include "scene/mesh/rig.h"

namespace toond::scene {

std::optional<std::size_t> Rig::find_clip(const std::string& name) const {
  for (std::size_t i = 0; i < clips.size(); ++i) {
    if (clips[i].name == name) return i;
  }
  // "Armature|Walk" answers to "Walk" when no other clip ends that way.
  std::optional<std::size_t> found;
  for (std::size_t i = 0; i < clips.size(); ++i) {
    const std::string& full = clips[i].name;
    const std::size_t bar = full.rfind('|');
    if (bar == std::string::npos || full.compare(bar + 1, std::string::npos, name) != 0) continue;
    if (found) return std::nullopt;
    found = i;
  }
  return found;
}

std::string Rig::clip_names() const {
  std::string list;
  for (const Clip& clip : clips) list += (list.empty() ? "\"" : ", \"") + clip.name + "\"";
  return list;
}

}  // namespace toond::scene
