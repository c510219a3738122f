// Intra-subgraph pose consistency (paper, "Subgraph Partition"; METHOD.md §3): the termination
// test of the recursive partition. A subgraph solution is consistent when
//   (a) loop consistency: every bounded loop (view_graph/cycles.hpp) of l < 8 cameras composes
//       its relative rotations to within 5° · floor((l − 1) / 2) of the identity, and
//   (b) relative-to-absolute consistency: for every valid edge <i, j>,
//         e_r = angle(R_ij, R̂_j R̂_i^T)                      ≤ 10°
//         e_t = angle(t_ij, t̂_ij),  t̂_ij = R̂_j (ĉ_i − ĉ_j)  ≤ 10°
//       where (R_ij, t_ij) is the edge's two-view relative pose (camera i -> camera j, pose.hpp)
//       and R̂, ĉ the solution's absolute poses. t̂_ij is exactly the translation of
//       RelativePoseBetween(P̂_i, P̂_j), so both sides are unit-free directions.
// Notation: the paper's P^j_i = (R^j_i, t^j_i) is our RelativePose i -> j (R^j_i = R_ij,
// t^j_i = t_ij): its e_t formula R̂_j^T (t̂_i − t̂_j) uses camera-to-world R̂ and centres t̂, which
// is R_j (c_i − c_j) = t_ij in our world-to-camera convention. So P^a_b reads "b expressed in
// a's frame", the map from b's coordinates to a's.
// Every violation is listed with the measured value and its threshold, for the pruning report.
#pragma once

#include <cstddef>
#include <map>
#include <vector>

#include "sfm_pruning/pruning/baseline_ratio_consistency.hpp"
#include "sfm_pruning/pruning/subgraph_solution.hpp"
#include "sfm_pruning/view_graph/cycles.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

struct ConsistencyTestOptions {
  bool test_loops = true;               // (a); ablation switch
  bool test_relative_rotation = true;   // (b) e_r
  bool test_relative_translation = true;  // (b) e_t
  // Loop tolerance step: a loop of l cameras may deviate by loop_step_deg · floor((l − 1) / 2).
  double loop_step_deg = 5.0;
  // Loop search; the paper tests loops of fewer than 8 cameras (max_cycle_length = 7).
  CycleSearchOptions cycles;
  double max_relative_rotation_error_deg = 10.0;     // e_r
  double max_relative_translation_error_deg = 10.0;  // e_t
  // e_t is skipped (not a violation) when |t_ij| or |t̂_ij| is below this: the direction is
  // undefined (coincident centres in the solution, or an edge without translation).
  double min_translation_norm = 1e-12;
  // (c) baseline ratios (not in the paper; baseline_ratio_consistency.hpp): a triplet violates
  // when its measured and implied ratios differ by more than this factor; 0 = off (the paper).
  // Needs the views' features, so TestBaselineRatios runs it, not TestSubgraphConsistency.
  double max_baseline_ratio_factor = 1.25;
  BaselineRatioOptions baseline_ratio;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

enum class ConsistencyTest { kLoop, kRelativeRotation, kRelativeTranslation, kBaselineRatio };

// "loop", "relative_rotation", "relative_translation", "baseline_ratio".
const char* ConsistencyTestName(ConsistencyTest test);

struct ConsistencyViolation {
  ConsistencyTest test = ConsistencyTest::kLoop;
  ViewPair edge{kUndefinedIndex, kUndefinedIndex};  // kRelative*: the edge
  ViewCycle loop;  // kLoop: the loop (canonical form); kBaselineRatio: (i, j, k), i the shared view
  // Degrees for the direction tests; for kBaselineRatio the factor between the measured and the
  // implied ratio (>= 1), so the report names the units per test.
  double value = 0.0;
  double threshold = 0.0;
};

struct ErrorSummary {
  size_t count = 0;  // number of measurements
  double max_deg = 0.0;
  double median_deg = 0.0;  // mean of the two middle values for an even count; 0 when empty
};

struct ConsistencyReport {
  bool consistent = true;
  std::vector<ConsistencyViolation> violations;  // loops first (search order), then edges (ViewPair order)
  ErrorSummary loop_error;
  ErrorSummary relative_rotation_error;
  ErrorSummary relative_translation_error;
  bool loop_search_truncated = false;
  // Valid edges with an endpoint that the solution does not pose: not tested.
  size_t num_unposed_edges = 0;
};

// Tests (c) when options.max_baseline_ratio_factor > 0: appends its violations to `report` (and
// marks it inconsistent on any); `views_and_intrinsics` and `features` give the bearings.
void TestBaselineRatios(const ViewGraph& graph, const SubgraphSolution& solution, const SfmData& views_and_intrinsics,
                        const FeaturesPerView& features, const ConsistencyTestOptions& options,
                        ConsistencyReport* report);

// Tests `solution` against the valid edges of `graph` (the subgraph's induced view graph).
ConsistencyReport TestSubgraphConsistency(const ViewGraph& graph, const SubgraphSolution& solution,
                                          const ConsistencyTestOptions& options = {});

}  // namespace sfm_pruning
