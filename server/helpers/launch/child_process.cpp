#include "helpers/launch/child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <optional>
#include <thread>

extern char** environ;

namespace toond::scene {
namespace {

using Clock = std::chrono::steady_clock;

class Fd {
 public:
  Fd() = default;
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd() { reset(); }
  int get() const { return fd_; }
  bool open() const { return fd_ >= 0; }
  void reset(int fd = -1) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = fd;
  }

 private:
  int fd_ = -1;
};

// A connected pair: `ours` stays here, `theirs` becomes a standard stream
// of the child. Both close on exec; the spawn's dup2 makes a copy that
// does not.
struct StdioLink {
  Fd ours;
  Fd theirs;
};

bool make_stdio_link(StdioLink& stdio_link) {
  int fds[2];
  if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0) return false;
  stdio_link.ours.reset(fds[0]);
  stdio_link.theirs.reset(fds[1]);
  return fcntl(fds[0], F_SETFL, fcntl(fds[0], F_GETFL) | O_NONBLOCK) == 0;
}

// Kills and reaps the child unless it was reaped already, whatever way
// run_child leaves (an exception included).
class ChildGuard {
 public:
  explicit ChildGuard(pid_t pid) : pid_(pid) {}
  ChildGuard(const ChildGuard&) = delete;
  ChildGuard& operator=(const ChildGuard&) = delete;
  ~ChildGuard() {
    if (pid_ > 0) kill_and_reap();
  }

  // The child's wait status after killing it and its process group.
  int kill_and_reap() {
    ::kill(-pid_, SIGKILL);
    ::kill(pid_, SIGKILL);
    int status = 0;
    while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    pid_ = -1;
    return status;
  }

  // The wait status once the child has ended on its own, or nullopt when
  // `deadline` comes first.
  std::optional<int> wait_until(Clock::time_point deadline) {
    auto pause = std::chrono::microseconds(200);
    for (;;) {
      int status = 0;
      const pid_t done = waitpid(pid_, &status, WNOHANG);
      if (done == pid_) {
        pid_ = -1;
        return status;
      }
      if (done < 0 && errno != EINTR) {
        // Not ours to wait for (SIGCHLD ignored): its status is lost, and
        // "exit 255" says so.
        pid_ = -1;
        return 255 << 8;
      }
      if (Clock::now() >= deadline) return std::nullopt;
      std::this_thread::sleep_for(pause);
      pause = std::min(pause * 2, std::chrono::microseconds(20000));
    }
  }

 private:
  pid_t pid_;
};

pid_t spawn(const ChildRun& run, StdioLink& in, StdioLink& out, StdioLink& err, int& error) {
  std::vector<std::string> words = {run.program};
  words.insert(words.end(), run.arguments.begin(), run.arguments.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, in.theirs.get(), STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, out.theirs.get(), STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, err.theirs.get(), STDERR_FILENO);
  // Nothing else of the daemon's (its listening socket, clients, model
  // files) reaches the child, close-on-exec or not.
  posix_spawn_file_actions_addclosefrom_np(&actions, 3);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  // A group of its own, so a timeout kills whatever it started too; signal
  // dispositions and mask as a fresh process has them (the daemon ignores
  // SIGPIPE, and ignored signals would survive the exec).
  sigset_t none;
  sigset_t all;
  sigemptyset(&none);
  sigfillset(&all);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  posix_spawnattr_setpgroup(&attributes, 0);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setsigdefault(&attributes, &all);
  pid_t pid = -1;
  error = posix_spawn(&pid, run.program.c_str(), &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  return error == 0 ? pid : -1;
}

// Reads what is there, keeping the first `keep` bytes; closes `fd` once
// the stream has ended or failed.
void drain(Fd& fd, std::string& into, std::size_t keep) {
  char chunk[1 << 16];
  for (;;) {
    const ssize_t n = recv(fd.get(), chunk, sizeof chunk, MSG_DONTWAIT);
    if (n > 0) {
      const std::size_t room = keep > into.size() ? keep - into.size() : 0;
      into.append(chunk, std::min(room, static_cast<std::size_t>(n)));
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) return;
    fd.reset();
    return;
  }
}

ChildResult ended(ChildResult result, int status) {
  if (WIFSIGNALED(status)) {
    result.end = ChildResult::End::Signalled;
    result.code = WTERMSIG(status);
  } else {
    result.end = ChildResult::End::Exited;
    result.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  return result;
}

}  // namespace

ChildResult run_child(const ChildRun& run) {
  ChildResult result;
  StdioLink in;
  StdioLink out;
  StdioLink err;
  if (!make_stdio_link(in) || !make_stdio_link(out) || !make_stdio_link(err)) {
    result.code = errno;
    return result;
  }
  int error = 0;
  const pid_t pid = spawn(run, in, out, err, error);
  if (pid < 0) {
    result.code = error;
    return result;
  }
  ChildGuard child(pid);
  in.theirs.reset();
  out.theirs.reset();
  err.theirs.reset();

  const Clock::time_point deadline = Clock::now() + run.time_limit;
  std::size_t written = 0;
  if (run.input.empty()) in.ours.reset();
  // One byte past the cap tells an answer that is too long from one that
  // fills it exactly.
  const std::size_t output_cap = run.max_output + 1;
  while (out.ours.open() || err.ours.open()) {
    // Rounded up, so that poll never wakes before the deadline and the run
    // is stopped at the deadline, not up to a millisecond ahead of it.
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) {
      result.end = ChildResult::End::TimedOut;
      child.kill_and_reap();
      return result;
    }
    pollfd polls[3];
    nfds_t count = 0;
    const auto watch = [&](Fd& fd, short events) {
      if (fd.open()) polls[count++] = {fd.get(), events, 0};
    };
    watch(in.ours, POLLOUT);
    watch(out.ours, POLLIN);
    watch(err.ours, POLLIN);
    if (poll(polls, count, static_cast<int>(std::min<long long>(left, 1000))) < 0 && errno != EINTR) break;
    if (in.ours.open()) {
      const ssize_t n =
          send(in.ours.get(), run.input.data() + written, run.input.size() - written, MSG_NOSIGNAL | MSG_DONTWAIT);
      if (n > 0) written += static_cast<std::size_t>(n);
      // The child may stop reading early (it has what it needs, or it
      // died): the rest of the input is not its concern any more.
      if (written == run.input.size() || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) {
        in.ours.reset();
      }
    }
    if (out.ours.open()) drain(out.ours, result.output, output_cap);
    if (err.ours.open()) drain(err.ours, result.errors, run.max_errors);
    if (result.output.size() > run.max_output) {
      result.end = ChildResult::End::OutputTooLarge;
      result.output.clear();
      child.kill_and_reap();
      return result;
    }
  }
  in.ours.reset();
  const std::optional<int> status = child.wait_until(deadline);
  if (!status) {
    result.end = ChildResult::End::TimedOut;
    child.kill_and_reap();
    return result;
  }
  return ended(std::move(result), *status);
}

}  // namespace toond::scene
