// The reconstruction controller: from a read input (views, intrinsics, features, matches or
// verified pairs) to a model, as `prunesfm reconstruct` and `prunesfm run` do, in one call for
// other programs (as COLMAP's and GLOMAP's mappers are):
//   1. view-graph focal calibration of the cameras whose focal is only a guess;
//   2. a quick solve that searches the focal of those the calibration could not determine;
//   3. verification of the pairs with those intrinsics (given two-view geometries: their poses
//      re-estimated from their inliers);
//   4. the engine, GLOBAL or GLOBAL_PRUNED (view-graph pruning, then the global solve);
//   5. when bundle adjustment moved a refined focal by more than the refocus threshold:
//      verification and engine once more with the refined intrinsics.
// Writing the outputs is the caller's (the CLI writes sfm_data.json, sparse/0, a PLY, timings).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <set>
#include <string>

#include "sfm_pruning/global/focal_calibration.hpp"
#include "sfm_pruning/global/global_engine.hpp"
#include "sfm_pruning/global/view_graph_builder.hpp"
#include "sfm_pruning/pipeline/intrinsics_refinement.hpp"
#include "sfm_pruning/pipeline/reconstruction_input.hpp"
#include "sfm_pruning/pruning/view_graph_pruning.hpp"
#include "sfm_pruning/report/run_view_graph.hpp"
#include "sfm_pruning/util/progress.hpp"

namespace sfm_pruning {

enum class ReconstructionEngine {
  kGlobal,        // GLOBAL: verification, rotation averaging, positioning, bundle adjustment
  kGlobalPruned,  // GLOBAL_PRUNED: the same after the view-graph pruning (pruning/)
};

// "GLOBAL", "GLOBAL_PRUNED" and back; ParseReconstructionEngine throws std::invalid_argument on
// any other name.
std::string ReconstructionEngineName(ReconstructionEngine engine);
ReconstructionEngine ParseReconstructionEngine(const std::string& name);

struct ReconstructionOptions {
  ReconstructionEngine engine = ReconstructionEngine::kGlobal;
  // Seed of every random choice (RANSAC, Louvain, positioning starts).
  uint64_t seed = 0;
  // Workers of the stages whose result does not depend on their number: verification, the
  // pruning's community solves and subgraph pairs (0: every core, ResolvedThreads()).
  int num_threads = 0;
  // Ceres threads of positioning and bundle adjustment. 1 (the default) keeps every output
  // bitwise reproducible for any num_threads; more are faster on large scenes, but Ceres's threaded
  // sums then change the last digits from run to run.
  int solver_threads = 1;
  PositioningMethod positioning = PositioningMethod::kGlobalPositioning;
  PositioningTracks positioning_tracks = PositioningTracks::kConnected;
  // GlobalEngineOptions::link_depth_votes.enabled of every solve (link_depth_votes.hpp).
  bool link_depth_votes = true;
  // Random starts of the positioning solve (GLOBAL_PRUNED: of its solve of the pruned graph),
  // each screened for this many iterations (docs/global.md, "Random starts"; GLOMAP: 1 start).
  int positioning_random_starts = 3;
  int positioning_start_screening_iterations = 25;
  // Verification: RelativePoseOptions::max_angular_error_deg and precision_check_ratio.
  double max_epipolar_error_deg = 0.25;
  double verification_precision_ratio = 0.5;
  ViewGraphPruningOptions pruning;  // GLOBAL_PRUNED only
  IntrinsicsRefinementOptions intrinsics;

  // num_threads, or every core when it is 0.
  int ResolvedThreads() const;

  // Throws std::invalid_argument naming the field when a value is out of range or a combination
  // cannot be honoured (MATCH_STARS tracks with translation averaging).
  void Check() const;
};

// The verification's options for `options` (seed, threads, thresholds).
ViewGraphBuildOptions VerificationOptions(const ReconstructionOptions& options);

// GLOBAL_PRUNED's options: the pruning options, the positioning of the per-community and final
// solves, and one seed / thread count for everything.
PrunedGlobalEngineOptions PrunedEngineOptions(const ReconstructionOptions& options);

// One line of what a reconstruction did (calibration, focal search, the view graph), for a log.
using ReconstructionLog = std::function<void(const std::string& line)>;

// The verified view graph of `input`: its two-view geometries (poses re-estimated from their
// inliers) or its putative matches, verified with the intrinsics of `scene` (input.scene when
// null). Throws Error naming input.source when there is nothing to match or every pair is
// rejected.
ViewGraph BuildVerifiedViewGraph(const ReconstructionOptions& options, const ReconstructionInput& input,
                                 ViewGraphBuildReport* report, const SfmData* scene = nullptr,
                                 const ProgressCallback& progress = {});

// View-graph focal calibration of the cameras `calibrated` into *scene, from the input's verified
// pairs, or from its matches verified once with the intrinsics of *scene.
FocalCalibrationReport CalibrateFocals(const ReconstructionOptions& options, const ReconstructionInput& input,
                                       const std::set<IndexT>& calibrated, SfmData* scene,
                                       const ProgressCallback& progress = {});

struct ReconstructionResult {
  bool success = false;
  std::string message;  // why the engine failed or kept fewer than two cameras; empty on success
  SfmData model;                                  // posed views, intrinsics as estimated, structure
  ViewGraphBuildReport build;                     // the verification of the final solve
  GlobalEngineReport engine;                      // the final solve
  std::optional<ViewGraphPruningReport> pruning;  // GLOBAL_PRUNED
  RunViewGraph view_graph;  // the verified graph with the pruning's cuts (`prunesfm report` draws it)
  std::optional<FocalCalibrationReport> calibration;  // when a focal was calibrated
  std::set<IndexT> refined_intrinsics;
  // Wall time of the stages before the engine's own (GlobalEngineReport::timings); 0 when a
  // stage did not run.
  double calibration_seconds = 0.0;
  double focal_search_seconds = 0.0;
  double first_pass_seconds = 0.0;  // verification and engine before the focal moved
  double verification_seconds = 0.0;
};

// Steps 1-5 above. Throws Error naming input.source when there is no edge to solve; a failed
// engine, or a final model with fewer than two cameras, returns success = false with the reason.
ReconstructionResult Reconstruct(const ReconstructionOptions& options, const ReconstructionInput& input,
                                 const ProgressCallback& progress = {}, const ReconstructionLog& log = {});

}  // namespace sfm_pruning
