#include "scene/draco_decoder.h"

#include <signal.h>
#include <string.h>

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <string>
#include <system_error>

#include "scene/child_process.h"

namespace toond::scene {
namespace {

constexpr std::uint64_t kSaturated = std::numeric_limits<std::uint64_t>::max() / 4;

std::uint64_t saturating_product(std::uint64_t a, std::uint64_t b) {
  return a != 0 && b > kSaturated / a ? kSaturated : a * b;
}

// The decoder holds its input, the decoded attributes and its connectivity
// tables: a kilobyte per point is several times what real meshes need, and
// the base covers the program and its libraries.
std::uint64_t memory_mb_for(const DracoJob& job) {
  const std::uint64_t bytes = (256ull << 20) + saturating_product(4, job.data.size()) +
                              saturating_product(1024, job.max_points);
  return std::min<std::uint64_t>(bytes >> 20, 1ull << 40) + 1;
}

// The largest answer the job can have: every attribute at 4 components of
// 4 bytes.
std::size_t answer_cap(const DracoJob& job) {
  const std::uint64_t per_attribute = 12 + saturating_product(16, job.max_points);
  const std::uint64_t bytes =
      64 + saturating_product(4, job.max_indices) + saturating_product(job.attributes.size(), per_attribute);
  return static_cast<std::size_t>(std::min<std::uint64_t>(bytes, std::numeric_limits<std::size_t>::max() / 2));
}

// The decoder's own reason, printable and short.
std::string reason_from(const std::string& errors) {
  std::string line = errors.substr(0, errors.find('\n')).substr(0, 200);
  std::replace_if(line.begin(), line.end(), [](char c) { return c < 0x20 || c > 0x7e; }, '?');
  return line.empty() ? "it gave no reason" : line;
}

std::string signal_name(int signal) {
  const char* abbreviation = sigabbrev_np(signal);
  return abbreviation ? "SIG" + std::string(abbreviation) : "signal " + std::to_string(signal);
}

std::string seconds_text(std::chrono::milliseconds time) {
  return std::to_string(time.count() / 1000) + "." + std::to_string(time.count() % 1000 / 100) + " s";
}

void check_answer(const draco_wire::Mesh& mesh, const DracoJob& job) {
  if (mesh.attributes.size() != job.attributes.size()) {
    throw DracoDecodeError("the decoder answered " + std::to_string(mesh.attributes.size()) + " attributes for " +
                           std::to_string(job.attributes.size()) + " asked for");
  }
  for (std::size_t k = 0; k < mesh.attributes.size(); ++k) {
    if (mesh.attributes[k].unique_id != job.attributes[k]) {
      throw DracoDecodeError("the decoder answered attribute " + std::to_string(mesh.attributes[k].unique_id) +
                             " where " + std::to_string(job.attributes[k]) + " was asked for");
    }
  }
}

}  // namespace

std::filesystem::path draco_decoder_program() {
  if (const char* set = std::getenv("TOOND_DRACO_DECODER"); set && *set) return set;
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  return (error ? std::filesystem::path() : self.parent_path()) / "toond-draco-decode";
}

draco_wire::Mesh decode_draco_mesh(const DracoJob& job) {
  ChildRun run;
  run.program = draco_decoder_program().string();
  const auto cpu_seconds = std::max<long long>(1, (job.time_limit.count() + 999) / 1000);
  run.arguments = {"--memory-mb", std::to_string(memory_mb_for(job)), "--cpu-seconds", std::to_string(cpu_seconds)};
  for (const std::uint32_t id : job.attributes) {
    run.arguments.push_back("--attribute");
    run.arguments.push_back(std::to_string(id));
  }
  run.input = std::string_view(reinterpret_cast<const char*>(job.data.data()), job.data.size());
  run.time_limit = job.time_limit;
  run.max_output = answer_cap(job);
  const ChildResult result = run_child(run);

  switch (result.end) {
    case ChildResult::End::NotStarted:
      throw DracoDecodeError("the Draco decoder " + run.program + " cannot be started (" +
                             std::error_code(result.code, std::generic_category()).message() + ")");
    case ChildResult::End::TimedOut:
      throw DracoDecodeError("the decoder took longer than " + seconds_text(job.time_limit) + " and was stopped");
    case ChildResult::End::OutputTooLarge:
      throw DracoDecodeError("the decoder answered more than the primitive's accessors can hold");
    case ChildResult::End::Signalled:
      if (result.code == SIGXCPU) {
        throw DracoDecodeError("the decoder used more than " + std::to_string(cpu_seconds) +
                               " s of processor time and was stopped");
      }
      throw DracoDecodeError("the decoder crashed (" + signal_name(result.code) + ")");
    case ChildResult::End::Exited:
      if (result.code == 1) throw DracoDecodeError(reason_from(result.errors));
      if (result.code != 0) {
        throw DracoDecodeError("the decoder stopped with status " + std::to_string(result.code) + ": " +
                               reason_from(result.errors));
      }
      break;
  }
  draco_wire::Mesh mesh;
  try {
    mesh = draco_wire::read_mesh(result.output);
  } catch (const draco_wire::WireError& e) {
    throw DracoDecodeError(std::string("the decoder's answer is not a mesh: ") + e.what());
  }
  check_answer(mesh, job);
  return mesh;
}

}  // namespace toond::scene
