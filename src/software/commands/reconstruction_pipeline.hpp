// The part `prunesfm reconstruct` and `prunesfm run` share: engine options on the command line,
// verification + engine, and the outputs (sfm_data.json, sparse/0, cloud_and_poses.ply,
// timings.json).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "software/commands/reconstruction_input.hpp"

namespace CLI {
class App;
}

namespace prunesfm {

struct EngineSettings {
  std::string engine = "GLOBAL";
  uint64_t seed = 0;
  int num_threads = 1;
  std::string positioning = "GLOMAP";  // or TRANSLATION_AVERAGING
};

// Adds --engine, --seed, --num_threads and --positioning to `cmd`.
void AddEngineOptions(CLI::App* cmd, EngineSettings* settings);

// Verifies (when the input holds putative matches), runs the engine and writes the outputs into
// `output`. Throws sfm_pruning::Error (one line naming input.source) when there is no edge or
// the engine fails. `read_seconds` is recorded in timings.json.
void RunReconstruction(const EngineSettings& settings, const ReconstructionInput& input,
                       const std::filesystem::path& output, double read_seconds);

}  // namespace prunesfm
