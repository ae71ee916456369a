#include "scene/gltf/draco_decoder.h"

#include <algorithm>
#include <limits>
#include <string>

#include "helpers/launch/child_process.h"
#include "helpers/launch/helper_program.h"

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
  const std::uint64_t bytes =
      (256ull << 20) + saturating_product(4, job.data.size()) + saturating_product(1024, job.max_points);
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

std::filesystem::path draco_decoder_program() { return helper_program("TOOND_DRACO_DECODER", "toond-draco-decode"); }

draco_wire::Mesh decode_draco_mesh(const DracoJob& job) {
  ChildRun run;
  run.program = draco_decoder_program().string();
  const auto cpu_seconds = helper_cpu_seconds(job.time_limit);
  run.arguments = {"--memory-mb", std::to_string(memory_mb_for(job)), "--cpu-seconds", std::to_string(cpu_seconds)};
  for (const std::uint32_t id : job.attributes) {
    run.arguments.push_back("--attribute");
    run.arguments.push_back(std::to_string(id));
  }
  run.input = std::string_view(reinterpret_cast<const char*>(job.data.data()), job.data.size());
  run.time_limit = job.time_limit;
  run.max_output = answer_cap(job);
  std::string answer;
  try {
    answer = run_helper(run, "the decoder", "answered more than the primitive's accessors can hold").output;
  } catch (const HelperError& e) {
    throw DracoDecodeError(e.what());
  }
  draco_wire::Mesh mesh;
  try {
    mesh = draco_wire::read_mesh(answer);
  } catch (const draco_wire::WireError& e) {
    throw DracoDecodeError(std::string("the decoder's answer is not a mesh: ") + e.what());
  }
  check_answer(mesh, job);
  return mesh;
}

}  // namespace toond::scene
