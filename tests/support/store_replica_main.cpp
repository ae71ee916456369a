// A replica of the model store in a process of its own, for tests that kill
// one mid-pass: opens the store in DATA (bounded to MAX_BYTES, 0 for none)
// and uploads padded models TAG:BYTES in turn, printing each id. With
// --die-at MOMENT:N it kills itself (SIGKILL: nothing is cleaned up) the
// Nth time the store reaches that moment of a pass (StoreOptions::checkpoint).
//   toond-test-store-replica DATA MAX_BYTES [--die-at MOMENT:N] TAG:BYTES...
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <string>
#include <string_view>

#include "scene/store/model_store.h"
#include "support/store_fixtures.h"

int main(int argc, char** argv) {
  if (argc < 3) {
    std::cerr << "usage: toond-test-store-replica DATA MAX_BYTES [--die-at MOMENT:N] TAG:BYTES...\n";
    return 2;
  }
  toond::scene::StoreOptions options;
  options.max_bytes = std::stoull(argv[2]);
  int first_upload = 3;
  std::string die_at;
  int die_count = 0;
  if (argc > 4 && std::string_view(argv[3]) == "--die-at") {
    const std::string spec = argv[4];
    die_at = spec.substr(0, spec.find(':'));
    die_count = std::stoi(spec.substr(spec.find(':') + 1));
    first_upload = 5;
  }
  int seen = 0;
  options.checkpoint = [&](std::string_view moment) {
    if (moment == die_at && ++seen == die_count) std::raise(SIGKILL);
  };
  try {
    toond::scene::ModelStore store(argv[1], options);
    for (int i = first_upload; i < argc; ++i) {
      const std::string spec = argv[i];
      const std::size_t colon = spec.find(':');
      const auto bundle = toond::test::padded_model(spec.substr(0, colon), std::stoul(spec.substr(colon + 1)));
      store.put(bundle);
    }
  } catch (const std::exception& e) {
    std::cerr << "toond-test-store-replica: " << e.what() << "\n";
    return 1;
  }
  return die_at.empty() ? 0 : 3;  // asked to die, and never reached the moment
}
