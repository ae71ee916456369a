// The daemon's listen queue holds many connections waiting for its accept
// thread. With httplib's own queue of 5, clients that connect while the
// accept thread cannot run (busy cores) are dropped by the kernel past the
// sixth: they wait a second for their SYN to be resent, or lose the
// connection (docs/performance.md). Here the daemon is stopped (SIGSTOP),
// so nothing is accepted, and 40 clients connect: the kernel completes the
// handshake of every one it has queue room for.
#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <vector>

#include "support/daemon.h"

namespace toond::test {
namespace {

// A connect() left to the kernel; the descriptor, or -1.
int start_connect(int port) {
  const int fd = socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK, 0);
  if (fd < 0) return -1;
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  connect(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address);
  return fd;
}

bool connected(int fd) {
  pollfd p{fd, POLLOUT, 0};
  if (poll(&p, 1, 0) != 1 || !(p.revents & POLLOUT)) return false;
  int error = 0;
  socklen_t size = sizeof error;
  return getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &size) == 0 && error == 0;
}

TEST(ListenBacklog, ConnectionsWaitInTheQueueWhileNothingIsAccepted) {
  Daemon daemon;
  const int port = daemon.port();
  ASSERT_EQ(kill(daemon.pid(), SIGSTOP), 0);
  constexpr int kClients = 40;
  std::vector<int> sockets;
  for (int i = 0; i < kClients; ++i) sockets.push_back(start_connect(port));
  // The handshakes the queue has room for complete at once on loopback;
  // the others would wait a second for their SYN to be resent.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(500);
  int established = 0;
  while (std::chrono::steady_clock::now() < deadline) {
    established = 0;
    for (const int fd : sockets) established += connected(fd) ? 1 : 0;
    if (established == kClients) break;
    usleep(10000);
  }
  ASSERT_EQ(kill(daemon.pid(), SIGCONT), 0);
  for (const int fd : sockets) close(fd);
  EXPECT_EQ(established, kClients) << "the listen queue held only " << established << " connections";
  // And the daemon still answers once it runs again.
  auto client = daemon.client();
  const auto health = client.Get("/healthz");
  ASSERT_TRUE(health);
  EXPECT_EQ(health->status, 200);
}

}  // namespace
}  // namespace toond::test
