#pragma once
// A zip archive with its files stored (not compressed): enough for tests
// that write 3MF packages, which are zip archives of XML parts.
#include <string>
#include <utility>
#include <vector>

namespace toond::test {

std::string stored_zip(const std::vector<std::pair<std::string, std::string>>& files);

}  // namespace toond::test
