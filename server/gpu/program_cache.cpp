#include "gpu/program_cache.h"

#include <algorithm>

namespace toond::gpu {

Program& ProgramCache::get(const std::string& vertex, const std::string& fragment,
                           std::vector<std::string> defines) {
  std::sort(defines.begin(), defines.end());
  std::string key = vertex + "|" + fragment;
  for (const auto& d : defines) key += "|" + d;
  auto it = programs_.find(key);
  if (it != programs_.end()) return *it->second;
  auto program = std::make_unique<Program>(ShaderSource{vertex, lookup_(vertex)},
                                           ShaderSource{fragment, lookup_(fragment)}, defines);
  return *programs_.emplace(key, std::move(program)).first->second;
}

}  // namespace toond::gpu
