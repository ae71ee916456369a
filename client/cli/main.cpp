// toon: the command-line client of toond. Parsing lives in cli_args, the
// requests in commands; this file only maps outcomes to exit statuses.
#include <iostream>
#include <string>
#include <vector>

#include "cli_args.h"
#include "commands.h"

int main(int argc, char** argv) {
  using namespace toond::cli;
  Options options;
  try {
    options = parse_args(std::vector<std::string>(argv + 1, argv + argc), server_from_environment());
  } catch (const UsageError& e) {
    std::cerr << "toon: " << e.what() << "\nTry 'toon --help'.\n";
    return 2;
  }
  if (options.help) {
    std::cout << usage_text(options.verb);
    return 0;
  }
  if (options.version) {
    std::cout << "toon " << TOOND_VERSION << "\n";
    return 0;
  }
  return run_command(options);
}
