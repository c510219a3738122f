// The part `prunesfm reconstruct` and `prunesfm run` share: engine options on the command line,
// verification + engine, and the outputs (sfm_data.json, sparse/0, cloud_and_poses.ply,
// timings.json, view_graph.json).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "sfm_pruning/global/view_graph_builder.hpp"
#include "sfm_pruning/pruning/view_graph_pruning.hpp"
#include "software/commands/intrinsics_options.hpp"
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
  std::string positioning_tracks = "CONNECTED";  // or MATCH_STARS
  // The command line's defaults (the library's: 1 start, as GLOMAP): three starts, each screened
  // for 25 iterations (docs/global.md, "Random starts").
  int positioning_random_starts = 3;  // GlobalEngineOptions::positioning_random_starts
  int positioning_start_screening = 25;  // GlobalEngineOptions::positioning_start_screening_iterations
  double max_epipolar_error_deg = 0.25;  // RelativePoseOptions::max_angular_error_deg
  double verification_precision_ratio = 0.5;  // RelativePoseOptions::precision_check_ratio
  sfm_pruning::ViewGraphPruningOptions pruning;  // GLOBAL_PRUNED and `prune`
  IntrinsicsSettings intrinsics;                 // reconstruct and run
};

// Adds --seed, --num_threads, --positioning, --positioning_tracks, --positioning_random_starts,
// --positioning_start_screening and the verification options (--max_epipolar_error_deg,
// --verification_precision_ratio) to `cmd`.
void AddSolverOptions(CLI::App* cmd, EngineSettings* settings);

// Adds --engine, the solver options, the intrinsics options (intrinsics_options.hpp) and the
// pruning options (pruning_options.hpp) to `cmd`.
void AddEngineOptions(CLI::App* cmd, EngineSettings* settings);

// GLOBAL_PRUNED's options from the settings: the pruning options, the positioning of the
// per-community and final solves, and one seed / thread count for everything.
sfm_pruning::PrunedGlobalEngineOptions PrunedEngineOptions(const EngineSettings& settings);

// The verified view graph of `input`: its two-view geometries (poses re-estimated from their
// inliers) or its putative matches, verified. Throws sfm_pruning::Error naming input.source when
// there is no edge, or when every pair is rejected. Verified with the intrinsics of `scene`
// (e.g. calibrated ones) when given, else of input.scene.
sfm_pruning::ViewGraph BuildVerifiedViewGraph(const EngineSettings& settings, const ReconstructionInput& input,
                                              sfm_pruning::ViewGraphBuildReport* report,
                                              const sfm_pruning::SfmData* scene = nullptr);

// A view graph and the report of the verification that built it.
struct VerifiedViewGraph {
  sfm_pruning::ViewGraph graph;
  sfm_pruning::ViewGraphBuildReport build;
};

// View-graph focal calibration (fundamental matrices) of the cameras `refined` into *scene, from
// the input's verified pairs, or from its matches verified once with the prior intrinsics; that
// graph goes to *prior_graph when given (it stays valid if the calibration changes no focal).
sfm_pruning::FocalCalibrationReport CalibrateFocals(const EngineSettings& settings, const ReconstructionInput& input,
                                                    const std::set<sfm_pruning::IndexT>& refined,
                                                    sfm_pruning::SfmData* scene,
                                                    std::optional<VerifiedViewGraph>* prior_graph = nullptr);

// A stage that ran before the input was read (the image front end of `prunesfm run IMAGES OUT`),
// listed first in timings.json; `reused` when a previous run's result was taken as is.
struct FrontEndStageTiming {
  std::string stage;
  double seconds = 0.0;
  bool reused = false;
};

// Verifies (when the input holds putative matches), runs the engine and writes the outputs into
// `output`. Throws sfm_pruning::Error (one line naming input.source) when there is no edge or
// the engine fails. `read_seconds` is recorded in timings.json.
void RunReconstruction(const EngineSettings& settings, const ReconstructionInput& input,
                       const std::filesystem::path& output, double read_seconds,
                       const std::vector<FrontEndStageTiming>& front_end = {});

}  // namespace prunesfm
