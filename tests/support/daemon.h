#pragma once
// Starts a real toond on 127.0.0.1 with port 0 and a fresh data directory,
// reads the "listening on http://..." line, and stops it (SIGTERM, then
// SIGKILL) when the fixture goes away.
#include <filesystem>
#include <string>
#include <vector>

#include <httplib.h>

namespace toond::test {

class Daemon {
 public:
  // `data_dir` empty: a new temporary directory, removed afterwards.
  explicit Daemon(std::filesystem::path data_dir = {}, std::vector<std::string> extra_args = {});
  ~Daemon();
  Daemon(const Daemon&) = delete;
  Daemon& operator=(const Daemon&) = delete;

  const std::string& url() const { return url_; }
  // The port of url(), which toond picked itself (--listen 127.0.0.1:0).
  int port() const { return std::stoi(url_.substr(url_.rfind(':') + 1)); }
  const std::filesystem::path& data_dir() const { return data_dir_; }
  httplib::Client client() const;
  // Sends SIGTERM and waits; returns the exit status (or -1).
  int stop();
  // SIGKILL: a crash, nothing finished or closed politely; then reaped.
  void crash();
  // SIGKILL, as a crash or power cut would end it; returns once it is gone.
  void kill_hard();
  int pid() const { return pid_; }
  bool running() const { return pid_ > 0; }

 private:
  std::filesystem::path data_dir_;
  bool own_data_dir_ = false;
  std::string url_;
  int pid_ = -1;
};

// A unique empty temporary directory.
std::filesystem::path make_temp_dir(const std::string& prefix);

// Runs a program to completion, returning exit status and captured output.
struct ProcessResult {
  int status = -1;
  std::string out;
  std::string err;
};
ProcessResult run_process(const std::vector<std::string>& argv, const std::vector<std::string>& extra_env = {});

}  // namespace toond::test
