#include "raw_http.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cctype>
#include <chrono>
#include <stdexcept>

namespace toond::test {
namespace {

// Whether `in` holds a status line, headers and as many body bytes as
// Content-Length says.
bool answer_complete(const std::string& in) {
  const auto head_end = in.find("\r\n\r\n");
  if (head_end == std::string::npos) return false;
  std::string head = in.substr(0, head_end);
  for (auto& c : head) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const auto at = head.find("\r\ncontent-length:");
  if (at == std::string::npos) return false;
  const std::size_t length = std::stoul(head.substr(at + 17));
  return in.size() >= head_end + 4 + length;
}

}  // namespace

RawAnswer send_raw(const std::string& url, const std::string& bytes, int timeout_s, bool hang_up) {
  const auto colon = url.rfind(':');
  const int port = std::stoi(url.substr(colon + 1));
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) throw std::runtime_error("socket failed");
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<std::uint16_t>(port));
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
    ::close(fd);
    throw std::runtime_error("cannot connect to " + url);
  }
  std::size_t sent = 0;
  while (sent < bytes.size()) {
    const ssize_t n = ::send(fd, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    if (n <= 0) break;  // the daemon may refuse and close before reading it all
    sent += static_cast<std::size_t>(n);
  }
  if (hang_up) ::shutdown(fd, SHUT_WR);
  std::string in;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeout_s);
  while (std::chrono::steady_clock::now() < deadline) {
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 100) <= 0) continue;
    char buf[8192];
    const ssize_t n = ::recv(fd, buf, sizeof buf, 0);
    if (n <= 0) break;
    in.append(buf, static_cast<std::size_t>(n));
    if (answer_complete(in)) break;  // a kept-alive connection need not close
  }
  ::close(fd);
  RawAnswer answer;
  const auto head_end = in.find("\r\n\r\n");
  answer.head = in.substr(0, head_end);
  if (head_end != std::string::npos) answer.body = in.substr(head_end + 4);
  if (in.rfind("HTTP/1.", 0) == 0 && in.size() > 12) answer.status = std::stoi(in.substr(9, 3));
  return answer;
}

}  // namespace toond::test
