#pragma once
// Stand-ins for toond's helper programs (toond-draco-decode,
// toond-assimp-convert) that crash, hang or answer nonsense: shell scripts
// in a temporary folder of their own, removed afterwards.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace toond::scene::test_checks {

class FakeHelpers {
 public:
  FakeHelpers() : dir_(std::filesystem::temp_directory_path() / ("toond-fake-helpers-" + std::to_string(getpid()))) {
    std::filesystem::create_directories(dir_);
  }
  ~FakeHelpers() { std::filesystem::remove_all(dir_); }
  FakeHelpers(const FakeHelpers&) = delete;
  FakeHelpers& operator=(const FakeHelpers&) = delete;

  // The path of an executable script running `body`.
  std::string make(const std::string& name, const std::string& body) {
    const auto path = dir_ / name;
    std::ofstream(path) << "#!/bin/sh\n" << body << "\n";
    std::filesystem::permissions(path, std::filesystem::perms::owner_all);
    return path.string();
  }

 private:
  std::filesystem::path dir_;
};

}  // namespace toond::scene::test_checks
