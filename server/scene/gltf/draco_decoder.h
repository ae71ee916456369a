#pragma once
// Decoding one Draco mesh in the helper program toond-draco-decode
// (server/helpers/draco_decode/), run with limits on time, memory and output: a
// crash, a hang or garbage from the decoder becomes a DracoDecodeError,
// never a crash of the daemon.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <vector>

#include "helpers/draco_decode/draco_wire.h"

namespace toond::scene {

class DracoDecodeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct DracoJob {
  std::span<const std::uint8_t> data;     // the Draco bytes
  std::vector<std::uint32_t> attributes;  // Draco unique ids to return, in this order
  // What the caller expects: they size the helper's memory limit and the
  // cap on its answer (the caller checks the counts it gets).
  std::uint64_t max_points = 0;
  std::uint64_t max_indices = 0;
  std::chrono::milliseconds time_limit{10000};
};

// How long one decode may take unless the import's own deadline is nearer.
inline constexpr std::chrono::milliseconds kDracoTimeLimit{10000};

// The helper program: $TOOND_DRACO_DECODER when set, else
// toond-draco-decode in the running executable's folder (where the build
// and the container image put it beside toond).
std::filesystem::path draco_decoder_program();

// The decoded mesh, its attributes in the order asked for, its indices
// below its points; DracoDecodeError with the reason otherwise.
draco_wire::Mesh decode_draco_mesh(const DracoJob& job);

}  // namespace toond::scene
