#pragma once
// Access to ../shared/models for tests. Tests call TOOND_REQUIRE_SHARED_MODELS()
// first, which skips (and says why) when the folder is not beside the checkout.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace toond::test {

inline std::filesystem::path shared_models_dir() { return TOOND_SHARED_MODELS; }

inline bool have_shared_models() { return std::filesystem::is_directory(shared_models_dir()); }

inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace toond::test

#define TOOND_REQUIRE_SHARED_MODELS()                                                     \
  do {                                                                                    \
    if (!::toond::test::have_shared_models())                                             \
      GTEST_SKIP() << "shared models not found at " << ::toond::test::shared_models_dir() \
                   << " (they live in ../shared/models beside the checkout)";             \
  } while (0)
