// Inter-subgraph edge pruning for one pair of subgraphs (k1, k2) (paper, "Inter-Subgraph Edge
// Pruning"; METHOD.md §4; docs/pruning.md):
//   1. every connecting edge <i, j> (i in k1, j in k2) places j in k1's frame by EPnP
//      (subgraph_edge_placement.hpp); edges that cannot be placed do not vote;
//   2. each voting edge gives the chained relative pose c1 -> i -> j -> c2 between the mean
//      poses, its translation affine in the scale β (chained_relative_pose.hpp);
//   3. RANSAC, num_ransac_iterations rounds (or every distinct sample once when there are at
//      most max_enumerated_samples): draw floor(sample_fraction · N) voting edges (at least
//      min_sample_size), fit β* and the sample means (rotation r̄, translation t̄), and count
//      every voting edge with E_r ≤ max_rotation_deviation_deg and
//      E_t = |t_e(β*) − t̄| ≤ max_translation_deviation_fraction · |t̄|. The largest consensus
//      set wins (ties: lowest total normalised error, then the earliest round); with
//      kMatchCoverage further runs on the leftover edges give more candidates
//      (hypothesis_selection). E_r is the angle to the geodesic mean of the sample's rotations. The voting edges outside the chosen
//      consensus are removed, each with its measured E_r / E_t under that hypothesis.
// The function only decides; invalidating the removed edges in the view graph is the caller's
// (InterSubgraphInvalidation gives the EdgeInvalidation to record).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/pruning/chained_relative_pose.hpp"
#include "sfm_pruning/pruning/subgraph_edge_placement.hpp"
#include "sfm_pruning/pruning/subgraph_solution.hpp"
#include "sfm_pruning/view_graph/view_graph_edge.hpp"

namespace sfm_pruning {

struct SubgraphAlignmentOptions {
  EdgePlacementOptions placement;

  int num_ransac_iterations = 30;  // paper: 30 (ablation 20 / 40)
  double sample_fraction = 0.4;     // of the voting edges, rounded down
  size_t min_sample_size = 2;       // β needs two edges
  // A run whose pool has at most this many distinct samples tries each of them once instead of
  // num_ransac_iterations random draws (not in the paper; ransac_samples.hpp): the search is
  // complete and the decision no longer depends on the seed. 1000 covers pools of up to 45 edges at
  // the sample of 2 (ViewGraphPruningOptions::max_sample_size). 0 = always the paper's random draws.
  size_t max_enumerated_samples = 1000;
  double max_rotation_deviation_deg = 5.0;           // E_r
  double max_translation_deviation_fraction = 0.05;  // E_t / |t̄|
  uint64_t seed = 0;                // RANSAC sampler (std::mt19937_64)

  // Which RANSAC hypothesis decides the pair. kLargestConsensus: the one with the most
  // consistent edges (the paper). kMatchCoverage: RANSAC is run again on the edges outside the
  // consensus sets found so far, up to max_hypotheses candidates; a candidate whose consensus
  // edges score Σ (matched − coverage_break_even · expected) landmarks < 0 (EdgePlacement's match
  // coverage) is ruled out, and the largest consensus among the others wins (if every candidate
  // is ruled out, the largest of all: real images re-detect fewer landmarks, and correct edges
  // score below the break-even too). Why: on
  // scenes whose copies fill the views (orbit_symmetric: 114 twin against 68 true edges between
  // two arcs) the twin edges are the larger consistent set, but each of them matches only the copy
  // and misses the unique texture its placed view should see (measured coverage ≤ 0.58 against
  // 0.6–0.9 for true edges; docs/pruning.md).
  enum class HypothesisSelection { kLargestConsensus, kMatchCoverage };
  HypothesisSelection hypothesis_selection = HypothesisSelection::kMatchCoverage;
  size_t max_hypotheses = 3;
  double coverage_break_even = 0.5;
  // When every candidate is ruled out (on real images a true edge re-detects well under half of
  // what it should see), a candidate is ruled out only against the pair's best: when its coverage
  // (matched / expected) is below this fraction of the best candidate's. The largest of the others
  // wins. 0: the largest of all wins. Real street, seed 1: the twin candidate of
  // {0005–0008}×{0000–0004} had 7 edges at coverage 0.13, the true one 6 edges at 0.31, and the
  // largest-of-all rule folded the street.
  double relative_coverage_break_even = 0.5;

  // When no sample gives a valid hypothesis (every edge lands on the same view j, or β ≤ 0) or no
  // hypothesis is supported by any edge, the chained rotations alone still separate a twin that
  // turns from the true edges (the courtyard's walls: 90°): the largest set of voting edges within
  // max_rotation_deviation_deg of one of them is kept when it has at least two edges
  // (kRotationOnly). Off: the paper, which keeps every voting edge of such a pair.
  bool rotation_only_fallback = true;

  // Pairs with fewer voting edges than this are not tested by RANSAC (the paper is silent).
  // With 1–2 votes there is no majority to tell the wrong edge from the right one.
  size_t min_edges_for_ransac = 3;
  enum class FewEdgesPolicy { kKeepAll, kRemoveAll };
  FewEdgesPolicy few_edges = FewEdgesPolicy::kKeepAll;

  // Edges that cannot vote (too few 2D–3D correspondences, failed PnP, j unposed in k2).
  enum class NonVotingPolicy { kKeep, kRemove };
  NonVotingPolicy non_voting_edges = NonVotingPolicy::kKeep;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

enum class SubgraphAlignmentStatus {
  kNoEdges,             // the subgraphs are not connected
  kAligned,             // RANSAC ran and found a hypothesis
  kTooFewVotingEdges,   // fewer than min_edges_for_ransac voting edges; few_edges policy applied
  kNoValidHypothesis,   // every sample was degenerate (no scale, β ≤ 0): voting edges kept
  kRotationOnly,        // no supported hypothesis with a scale; the rotation-only consensus decided
                        // (rotation_only_fallback); no frame transform
};

const char* SubgraphAlignmentStatusName(SubgraphAlignmentStatus status);

enum class InterSubgraphVerdict {
  kConsistent,            // kept: in the consensus set
  kRotationDeviation,     // removed: E_r above the threshold
  kTranslationDeviation,  // removed: E_r fine, E_t above the threshold
  kCannotVote,            // kept or removed by non_voting_edges
  kFewEdges,              // kept or removed by few_edges
  kUnjudged,              // kept: no valid RANSAC hypothesis
  kLoopInconsistent,      // removed with its whole pair: the pair's frame transform breaks the
                          // loops of subgraphs (subgraph_loop_consistency.hpp)
  kUnverified,            // removed with its whole pair: redundant, and nothing verifies it
                          // against the trusted forest (trusted_link_forest.hpp)
  kModelDisagreement,     // kept by the pruning, removed by the audit against the model solved from
                          // the pruned graph (model_edge_audit.hpp)
  kLandmarkDisagreement,  // kept by the pruning, but too few of its matches agree with the two
                          // subgraphs' landmarks (landmark_match_check.hpp)
  kCapturePathRotation,   // removed before the partition: its rotation deviates from the capture
                          // path's (capture_path_rotations.hpp)
  kMissingCorrespondences,  // kept by the pruning, removed because its views miss the landmarks the
                            // model solved from the pruned graph predicts in them
                            // (missing_correspondence_check.hpp)
  kCapturePathDirection,    // removed before the partition: its translation direction deviates from
                            // the capture path's model (capture_path_directions.hpp)
};

const char* InterSubgraphVerdictName(InterSubgraphVerdict verdict);

struct InterSubgraphEdgeDecision {
  EdgePlacement placement;  // view_i in k1, view_j in k2, PnP outcome
  bool j_posed_in_k2 = true;  // false: no P̂_j^k2, the edge cannot vote even when placed
  bool voted = false;         // placed and posed: took part in RANSAC
  bool kept = true;
  InterSubgraphVerdict verdict = InterSubgraphVerdict::kConsistent;
  // Under the selected hypothesis (0 when the edge did not vote or no hypothesis exists).
  double rotation_deviation_deg = 0.0;
  double translation_deviation = 0.0;  // k1 units
  double translation_threshold = 0.0;  // max_translation_deviation_fraction · |t̄|
};

// One candidate of the RANSAC (one per run; a single one under kLargestConsensus).
struct AlignmentHypothesis {
  size_t consensus_size = 0;   // voting edges within the thresholds
  double beta = 1.0;
  size_t expected_landmarks = 0;  // Σ over the consensus edges (EdgePlacement coverage)
  size_t matched_landmarks = 0;
  double coverage_score = 0.0;  // matched − coverage_break_even · expected
  // Ruled out by the coverage (below the break-even, or, when every candidate is, relatively to
  // the best one's coverage; or empty beside a supported candidate), as the selection saw it.
  bool ruled_out = false;
  int num_samples = 0;      // samples its RANSAC run tried
  bool enumerated = false;  // every distinct sample of the run's pool (Options::max_enumerated_samples)

  // matched / expected; infinity when nothing was expected (no evidence against the candidate).
  double Coverage() const {
    return expected_landmarks > 0 ? static_cast<double>(matched_landmarks) / static_cast<double>(expected_landmarks)
                                  : std::numeric_limits<double>::infinity();
  }
};

struct SubgraphAlignmentResult {
  SubgraphAlignmentStatus status = SubgraphAlignmentStatus::kNoEdges;
  // The selected hypothesis (kAligned only): scale k2 -> k1, mean chained rotation and
  // translation c1 -> c2 in k1 units.
  double beta = 1.0;
  Eigen::Matrix3d mean_rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d mean_translation = Eigen::Vector3d::Zero();
  // The frame transform the selected hypothesis implies, X_k1 = k2_to_k1(X_k2)
  // (FrameSimilarityOfChain), and its consensus size: the input of the loop check across pairs
  // (subgraph_loop_consistency.hpp). Set for every aligned pair.
  bool has_frame_transform = false;
  Similarity3 k2_to_k1;
  size_t consensus_size = 0;
  int best_iteration = -1;
  size_t num_voting_edges = 0;
  size_t sample_size = 0;
  size_t num_valid_hypotheses = 0;
  std::vector<AlignmentHypothesis> hypotheses;  // in the order found
  int selected_hypothesis = -1;                 // index into hypotheses (kAligned only)
  std::vector<InterSubgraphEdgeDecision> edges;  // one per connecting edge, (i, j) order

  std::vector<ViewPair> KeptEdges() const;     // oriented (i, j)
  std::vector<ViewPair> RemovedEdges() const;  // oriented (i, j)
};

// The reason to record for a removed edge: kInterSubgraphInconsistent with E_r (deg, threshold
// deg) or E_t / |t̄| (threshold max_translation_deviation_fraction); kOther with the number of
// correspondences (cannot vote) or of voting edges (few edges). reason kNone for a kept edge.
EdgeInvalidation InterSubgraphInvalidation(const InterSubgraphEdgeDecision& decision,
                                           const SubgraphAlignmentOptions& options);

// Decides the connecting edges of (k1, k2) in `graph`. `views_and_intrinsics` supplies the views
// and intrinsics of the j images, `features` their keypoints.
SubgraphAlignmentResult AlignSubgraphPair(const ViewGraph& graph, const SubgraphSolution& k1,
                                          const SubgraphSolution& k2, const SfmData& views_and_intrinsics,
                                          const FeaturesPerView& features,
                                          const SubgraphAlignmentOptions& options = {});

// A connecting edge judged against a frame transform found elsewhere (JudgeEdgesAgainstTransform).
struct EdgeAgainstTransform {
  bool voted = false;   // placed in k1 and posed in k2: judged
  bool agrees = false;  // within max_rotation_deviation_deg and max_translation_deviation_fraction
  double rotation_deviation_deg = 0.0;           // E_r
  double translation_deviation_fraction = 0.0;   // E_t over |t̄|
};

// The connecting edges of `alignment` (computed by AlignSubgraphPair(graph, k1, k2, ...)) judged
// against a frame transform found elsewhere, X_k1 = k2_to_k1(X_k2), by the RANSAC's consensus test:
// the transform stands in for a hypothesis (its scale as β, the pose of k2's mean camera it implies
// in k1 as the mean chained pose). One entry per edge.
std::vector<EdgeAgainstTransform> JudgeEdgesAgainstTransform(const SubgraphAlignmentResult& alignment,
                                                             const SubgraphSolution& k1, const SubgraphSolution& k2,
                                                             const Similarity3& k2_to_k1,
                                                             const SubgraphAlignmentOptions& options);

}  // namespace sfm_pruning
