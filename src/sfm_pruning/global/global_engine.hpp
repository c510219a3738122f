// The GLOBAL engine (METHOD.md §2): a verified view graph -> posed cameras and landmarks.
//
//   rotation averaging (filters edges > 10 deg, keeps the largest component)
//   -> tracks (min length 3; 2 for graphs of at most 3 views) from the links whose depth the
//      features' other links confirm (link_depth_votes.hpp)
//   -> positioning: global positioning (GLOMAP, default; solved on the tracks or on match stars)
//      or translation averaging
//   -> num_bundle_rounds x (bundle adjustment -> structure filtering -> retriangulation), the
//      first adjustment on a well-distributed subset of the landmarks
//   -> final bundle adjustment and structure filtering
//      (with the distortion evidence test: with the distortion held, then one adjustment with it
//      free; if BIC says the data determine it, the schedule again, distortion free throughout)
//   -> views left with too few observations are unregistered.
//
// No I/O: the pruning engine calls it once per subgraph. Deterministic for a seed with
// num_threads = 1 (bitwise); more threads only change Ceres' summation order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "sfm_pruning/global/bundle_adjustment.hpp"
#include "sfm_pruning/global/distortion_evidence.hpp"
#include "sfm_pruning/global/global_positioning.hpp"
#include "sfm_pruning/global/link_depth_votes.hpp"
#include "sfm_pruning/global/match_star_tracks.hpp"
#include "sfm_pruning/global/retriangulation.hpp"
#include "sfm_pruning/global/rotation_averaging.hpp"
#include "sfm_pruning/global/structure_filtering.hpp"
#include "sfm_pruning/global/subset_bundle_adjustment.hpp"
#include "sfm_pruning/global/tracks.hpp"
#include "sfm_pruning/global/translation_averaging.hpp"
#include "sfm_pruning/global/view_graph_builder.hpp"
#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/util/progress.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

enum class PositioningMethod {
  kGlobalPositioning,     // GLOMAP: cameras and points jointly from the rays (default)
  kTranslationAveraging,  // camera centres from the edge directions, then points
};

// The tracks global positioning solves with (the structure always comes from the union-find tracks).
enum class PositioningTracks {
  kConnected,   // the union-find tracks (tracks.hpp), as GLOMAP (default)
  kMatchStars,  // one star per feature and its direct matches (match_star_tracks.hpp): a wrong
                // match between copies of a repeated texture misplaces one observation, not a track
};

struct GlobalEngineOptions {
  RotationAveragingOptions rotation;  // max_relative_rotation_error_deg = 10
  // min_track_length = 3, lowered to 2 when the rotation averaging keeps at most 3 views.
  TrackBuildingOptions tracks;
  // Links (inlier matches) whose depth the feature's other links contradict stay out of the tracks.
  LinkDepthVoteOptions link_depth_votes;
  PositioningMethod positioning = PositioningMethod::kGlobalPositioning;
  GlobalPositioningOptions global_positioning;
  PositioningTracks positioning_tracks = PositioningTracks::kConnected;  // global positioning only
  TranslationAveragingOptions translation_averaging;
  // Intrinsics held constant by default (refine_focal / refine_principal_point available).
  BundleAdjustmentOptions bundle;
  StructureFilteringOptions filtering;  // 4 px, 1.5 deg
  RetriangulationOptions retriangulation;
  // Rounds of adjust -> filter -> retriangulate before the final adjust -> filter.
  int num_bundle_rounds = 2;
  // The first adjustment (from the positioning, far from the optimum) runs on a well-distributed
  // subset of the landmarks, up to this many per view, and re-triangulates the others
  // (subset_bundle_adjustment.hpp); max_tracks_per_view = 0 adjusts all of them.
  TrackSubsamplingOptions first_bundle_subsampling{500, 8};
  // Ceres' function tolerances (relative cost decrease at which a solve stops) that override the
  // estimators' own defaults, which are tight so that unit tests on exact data reach the exact
  // solution. On real data the last digits cost tens of iterations and change nothing that
  // matters: from a random start the positioning's last iterations mostly move its free scale;
  // under the Huber loss bundle adjustment converges linearly (fountain-P11: 40+ iterations from
  // 1e-5 to 1e-6 for a 0.1 % lower cost, same poses to 0.01 AUC); and the adjustments before the
  // last are followed by filtering and retriangulation, which change the problem anyway.
  double positioning_function_tolerance = 1e-6;   // both positioning methods (solver: 1e-10)
  // Iteration cap of each positioning solve (both methods; solver default 200, for exact data).
  // GLOMAP's value. Scenes that converge take 24-125 iterations over both solves (random start,
  // then the re-solve after ray rejection); courtyard, whose twin edges leave no consistent
  // solution, ran into the cap with 200 iterations in its first solve, 2.6 s of its 4.7 s.
  int positioning_max_num_iterations = 100;
  // ... and of each re-solve after ray rejection, which starts from the previous solution. On the
  // bench scenes that converge it takes 6-53 iterations (clean 6, castle-P19 25,
  // sequential_large@500 53, measured with no cap; a cap of 50 changed @500's result); on folded
  // ones it runs on without changing the result (courtyard: into the cap of 100, 0.6 s more than
  // with 60, AUC@10 22.02 against 22.06).
  int positioning_max_num_resolve_iterations = 60;
  // Random starts of each positioning solve (both methods; PositioningSolverOptions::
  // num_random_starts): the one whose solution agrees with the most rays is kept. 1 = GLOMAP's
  // single start; each further start costs one more solve.
  int positioning_random_starts = 1;
  // PositioningSolverOptions::start_screening_iterations (both methods).
  int positioning_start_screening_iterations = 0;
  double intermediate_function_tolerance = 1e-4;  // adjustments before the last
  double final_function_tolerance = 1e-5;         // the last adjustment (GLOMAP's value)
  // Iteration cap of the adjustments before the last (the last keeps bundle.max_num_iterations).
  // Under the Huber loss, with outlier observations not yet filtered, they converge linearly:
  // on sequential_large@2000 they took 72 and 61 iterations at 1.2-1.4 s each to reach 1e-4, most
  // of them shaving the last 3 % off the cost, which the filter then changes anyway.
  int intermediate_max_num_iterations = 25;
  // When bundle.refine_distortion: adjust with the distortion held, then keep a last adjustment
  // with it free only if the cost it saves pays BIC's price (distortion_evidence.hpp).
  // false: refine it from the first adjustment on.
  bool distortion_needs_evidence = true;
  // false: stop after the positioning (no adjustment, no filter: the model audit's quick solve).
  bool bundle_adjust = true;
  // After the final filter, views observing fewer landmarks than this lose their pose.
  size_t min_observations_per_view = 10;
  // Overrides the positioning solvers' seeds (both methods).
  uint64_t seed = 0;
  // Ceres threads of positioning and bundle adjustment (1 = bitwise reproducible).
  int num_threads = 1;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

// The schedule of a solve whose only product is the focal length of cameras that the view-graph
// calibration could not determine (focal_calibration.hpp: a ring of cameras looking at its
// centre leaves the pairs' cost flat). Bundle adjustment finds such a focal, but slowly: focal
// and scene depth trade off along a curved valley, so Levenberg-Marquardt moves the focal by
// about 1 % per iteration (templeSparseRing: 768 -> 1509 px took 120 iterations over three
// adjustments, 1 s of its 1.9 s). The search therefore runs one adjustment, no filtering rounds,
// on max_tracks_per_view well-spread landmarks per view, for at most max_num_iterations
// iterations; the caller verifies and solves again with the focal it found.
struct FocalSearchSchedule {
  size_t max_tracks_per_view = 30;
  // templeSparseRing reached 1475 px in 100 iterations (the full solve then moved it by 8 % on
  // its own front end's matches and had to solve again) and 1483-1490 px in 200.
  int max_num_iterations = 200;
};
GlobalEngineOptions WithFocalSearchSchedule(GlobalEngineOptions options, const FocalSearchSchedule& schedule = {});

struct StageTiming {
  std::string stage;  // "rotation averaging", "tracks", "positioning", "bundle adjustment", ...
  double seconds = 0.0;  // wall time
};

struct GlobalEngineReport {
  bool success = false;
  std::string message;  // why it failed (empty on success)

  std::vector<StageTiming> timings;  // in execution order
  double total_seconds = 0.0;

  size_t num_input_views = 0;       // nodes of the input graph
  size_t num_input_edges = 0;       // valid edges of the input graph
  size_t num_rotation_edges = 0;    // valid edges between the views kept by rotation averaging
  size_t num_filtered_edges = 0;    // invalidated by the rotation filter
  size_t num_depth_inconsistent_links = 0;  // kept out of the tracks by link_depth_votes
  size_t num_tracks = 0;
  size_t num_registered_views = 0;  // posed views of the output
  size_t num_landmarks = 0;
  size_t num_observations = 0;
  double final_rms_px = 0.0;        // of the last bundle adjustment
  std::vector<DroppedView> dropped_views;  // view id order

  RotationAveragingResult rotation;
  TrackBuildingResult track_counts;  // tracks themselves cleared
  PositioningResult positioning;
  std::vector<BundleAdjustmentResult> bundle_adjustments;
  DistortionEvidence distortion;  // tested only when the distortion was refined
};

// Reconstructs the views of `graph` (valid edges only; the graph is copied, not modified).
// `views_and_intrinsics` supplies views + intrinsics (poses and structure are ignored); `out`
// receives them with the estimated poses and landmarks (landmark observations name feature ids).
// On failure out holds the views and intrinsics without poses and report->success is false.
// Progress: the stage names of the estimators plus "bundle adjustment". Throws std::invalid_argument
// when options.Check() does.
void RunGlobalEngine(const GlobalEngineOptions& options, const ViewGraph& graph,
                     const SfmData& views_and_intrinsics, const FeaturesPerView& features, SfmData* out,
                     GlobalEngineReport* report, const ProgressCallback& progress = {});

// The engine's stages after the positioning, from the poses of `initial` instead of a solve:
// the views `initial` poses keep their poses (the other views of `graph` are dropped), the tracks
// of `graph` among them are triangulated from those poses, then adjusted and filtered as in
// RunGlobalEngine. For a graph that differs by a few edges from the one `initial` was solved from
// (the model audit, view_graph_pruning.hpp): the rotation averaging and the positioning, most of a
// solve's time, are not repeated. Same output contract as RunGlobalEngine (`out` keeps the
// intrinsics of `initial`). Throws std::invalid_argument when options.Check() does.
void RefineGlobalModel(const GlobalEngineOptions& options, const ViewGraph& graph, const SfmData& initial,
                       const FeaturesPerView& features, SfmData* out, GlobalEngineReport* report,
                       const ProgressCallback& progress = {});

}  // namespace sfm_pruning
