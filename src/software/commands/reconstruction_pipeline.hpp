// The part `prunesfm reconstruct` and `prunesfm run` share: engine options on the command line,
// the library's reconstruction controller (sfm_pruning/pipeline/reconstruction.hpp), and the
// outputs (sfm_data.json, sparse/0, cloud_and_poses.ply, timings.json, view_graph.json).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "sfm_pruning/pipeline/reconstruction.hpp"
#include "sfm_pruning/pruning/view_graph_pruning.hpp"
#include "software/commands/intrinsics_options.hpp"

namespace CLI {
class App;
}

namespace prunesfm {

// The flags of sfm_pruning::ReconstructionOptions (pipeline/reconstruction.hpp says what each
// does), its enumerations by their names on the command line.
struct EngineSettings {
  std::string engine = "GLOBAL";
  uint64_t seed = 0;
  int num_threads = 0;     // 0: every core (ReconstructionOptions::num_threads)
  int solver_threads = 1;  // ReconstructionOptions::solver_threads
  std::string positioning = "GLOMAP";  // or TRANSLATION_AVERAGING
  std::string positioning_tracks = "CONNECTED";  // or MATCH_STARS
  bool link_depth_votes = true;  // ReconstructionOptions::link_depth_votes
  // Three starts, each screened for 25 iterations (docs/global.md, "Random starts"), as
  // ReconstructionOptions; GlobalEngineOptions used alone has GLOMAP's single start.
  int positioning_random_starts = 3;  // GlobalEngineOptions::positioning_random_starts
  int positioning_start_screening = 25;  // GlobalEngineOptions::positioning_start_screening_iterations
  double max_epipolar_error_deg = 0.25;  // RelativePoseOptions::max_angular_error_deg
  double verification_precision_ratio = 0.5;  // RelativePoseOptions::precision_check_ratio
  // A COLMAP database's verified pairs re-verified from their raw matches (ReverifyDatabasePairs;
  // docs/global.md, "The view graph"). Off: the development and held-out splits disagree on it.
  bool reverify_database_pairs = false;
  sfm_pruning::ViewGraphPruningOptions pruning;  // GLOBAL_PRUNED and `prune`
  IntrinsicsSettings intrinsics;                 // reconstruct and run
};

// A COLMAP database's input; its images (the points' colours) under `image_path` when given; its
// verified pairs handed to the own verification when `settings.reverify_database_pairs`.
sfm_pruning::ReconstructionInput ReadDatabaseInput(const std::string& database, const std::string& image_path,
                                                   const EngineSettings& settings);

// Adds --seed, --num_threads, --solver_threads, --positioning, --positioning_tracks, --positioning_random_starts,
// --positioning_start_screening and the verification options (--max_epipolar_error_deg,
// --verification_precision_ratio) to `cmd`.
void AddSolverOptions(CLI::App* cmd, EngineSettings* settings);

// Adds --engine, --reverify_database_pairs, the solver options, the intrinsics options
// (intrinsics_options.hpp) and the pruning options (pruning_options.hpp) to `cmd`.
void AddEngineOptions(CLI::App* cmd, EngineSettings* settings);

// The library's options (pipeline/reconstruction.hpp) for the settings the flags filled.
sfm_pruning::ReconstructionOptions ToReconstructionOptions(const EngineSettings& settings);

// A stage that ran before the input was read (the image front end of `prunesfm run IMAGES OUT`),
// listed first in timings.json; `reused` when a previous run's result was taken as is.
struct FrontEndStageTiming {
  std::string stage;
  double seconds = 0.0;
  bool reused = false;
};

// Runs the reconstruction controller (sfm_pruning::Reconstruct) and writes its outputs into
// `output`. Throws sfm_pruning::Error (one line naming input.source) when there is no edge or
// the engine fails. `read_seconds` is recorded in timings.json.
void RunReconstruction(const EngineSettings& settings, const sfm_pruning::ReconstructionInput& input,
                       const std::filesystem::path& output, double read_seconds,
                       const std::vector<FrontEndStageTiming>& front_end = {});

}  // namespace prunesfm
