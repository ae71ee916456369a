#pragma once
// Whole byte strings through standard input and output, for the helper
// programs (toond-draco-decode, toond-assimp-convert) that answer the daemon
// over pipes.
#include <string>

namespace toond::helper_process {

// Everything on standard input, up to its end (or a read error).
std::string read_all_stdin();
// Writes all of `bytes`; false when the other end went away.
bool write_all_stdout(const std::string& bytes);

}  // namespace toond::helper_process
