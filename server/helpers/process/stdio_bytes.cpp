#include "helpers/process/stdio_bytes.h"

#include <unistd.h>
#include <cerrno>

namespace toond::helper_process {

std::string read_all_stdin() {
  std::string input;
  char chunk[1 << 16];
  for (;;) {
    const ssize_t n = read(STDIN_FILENO, chunk, sizeof chunk);
    if (n > 0) {
      input.append(chunk, static_cast<std::size_t>(n));
    } else if (n == 0 || errno != EINTR) {
      return input;
    }
  }
}

bool write_all_stdout(const std::string& bytes) {
  std::size_t at = 0;
  while (at < bytes.size()) {
    const ssize_t n = write(STDOUT_FILENO, bytes.data() + at, bytes.size() - at);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    at += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace toond::helper_process
