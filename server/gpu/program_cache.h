#pragma once
// Programs compiled once per variant and kept: the key is the stage files
// plus the sorted #defines, so a request that needs the same features as an
// earlier one reuses its program.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gpu/program.h"

namespace toond::gpu {

class ProgramCache {
 public:
  // Returns the GLSL text of a shader file; throws GpuError when missing.
  using SourceLookup = std::function<std::string(const std::string& name)>;
  explicit ProgramCache(SourceLookup lookup) : lookup_(std::move(lookup)) {}

  Program& get(const std::string& vertex, const std::string& fragment,
               std::vector<std::string> defines);
  std::size_t size() const { return programs_.size(); }
  void clear() { programs_.clear(); }

 private:
  SourceLookup lookup_;
  std::map<std::string, std::unique_ptr<Program>> programs_;
};

}  // namespace toond::gpu
