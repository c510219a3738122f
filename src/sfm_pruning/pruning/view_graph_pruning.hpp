// Subgraph-guided view-graph pruning (paper, "Overview"; METHOD.md §3–4) and the GLOBAL_PRUNED
// engine built on it.
//
// PruneViewGraph:
//   1. the largest connected component of the valid graph is partitioned recursively
//      (recursive_partition.hpp: Louvain + RunGlobalEngine per community + consistency tests);
//      views outside it are left alone (the final solve drops them anyway);
//   2. every pair of accepted subgraphs (k1 < k2 in acceptance order, so k1 is the earlier,
//      usually larger one whose points place k2's views) joined by valid edges is aligned
//      (AlignSubgraphPair, in parallel over pairs), which decides its connecting edges;
//   3. the loops of aligned pairs are checked (subgraph_loop_consistency.hpp): a pair whose frame
//      transform breaks more subgraph triangles than it closes loses all its connecting edges
//      (kSubgraphLoopInconsistent), and so does the pair of lowest match coverage on a longer
//      cycle that does not close (subgraph_cycle_consistency.hpp);
//   4. the removed edges are invalidated in the graph: those of a loop-rejected pair with
//      kSubgraphLoopInconsistent, the others with InterSubgraphInvalidation
//      (kInterSubgraphInconsistent + the measured error).
// Edges inside an accepted subgraph are never touched.
//
// RunPrunedGlobalEngine (GLOBAL_PRUNED) = PruneViewGraph on a copy of the graph, then
// RunGlobalEngine on the pruned graph (which keeps its largest component). With the audit
// (model_edge_audit.hpp) that solve runs the audit's lighter schedule, the inter-subgraph edges are
// judged against its model, removed ones that it transfers re-admitted and kept ones it does not
// removed, and the audited graph is adjusted from that model's poses (RefineGlobalModel) or solved
// again (ModelEdgeAuditOptions::model_schedule, refine_final). With the missing-correspondence check
// (missing_correspondence_check.hpp, on by default) the pruned graph is solved, the kept edges
// between subgraphs whose views miss the landmarks the model predicts in them are removed, and it is
// solved again, while edges go.
#pragma once

#include <string>
#include <vector>

#include "sfm_pruning/global/global_engine.hpp"
#include "sfm_pruning/pruning/landmark_match_check.hpp"
#include "sfm_pruning/pruning/missing_correspondence_check.hpp"
#include "sfm_pruning/pruning/model_edge_audit.hpp"
#include "sfm_pruning/pruning/pair_trust.hpp"
#include "sfm_pruning/pruning/recursive_partition.hpp"
#include "sfm_pruning/pruning/capture_order.hpp"
#include "sfm_pruning/pruning/capture_path_directions.hpp"
#include "sfm_pruning/pruning/capture_path_rotations.hpp"
#include "sfm_pruning/pruning/subgraph_alignment.hpp"
#include "sfm_pruning/pruning/subgraph_loop_consistency.hpp"
#include "sfm_pruning/pruning/trusted_link_forest.hpp"

namespace sfm_pruning {

struct ViewGraphPruningOptions {
  // The capture-order prior (capture_order.hpp): the partition and the loop check of subgraph
  // pairs favour the edges between views taken one after the other, when the order is informative.
  CaptureOrderOptions capture_order;
  RecursivePartitionOptions partition;
  SubgraphAlignmentOptions alignment;
  // Cap on the RANSAC sample of a pair (0 = no cap, the paper's plain fraction). The paper's
  // 0.4·|E'| draws samples of dozens of edges on large pairs (orbit_symmetric, 36 views: 182
  // edges, sample 72); with a third of them twins no sample is ever clean, its mean pose fits
  // nobody and the whole pair is cut (measured: 630 -> 205 edges, 14 of 36 views registered).
  // With the cap the fraction is lowered to max_sample_size / |E'| for that pair only. The cap is
  // the minimal sample (β needs two edges): with 4, the 5 true edges among the 21 between two
  // subgraphs of the real street made a clean sample with chance 5/5985 per round, and the true
  // transform was never found; with 2 the chance is 10/210 (street AUC@5 ≥ 90 for 7 of 10 seeds
  // against 3 of 10 with 4; orbit_symmetric, books and the clean scenes unchanged).
  size_t max_sample_size = 2;
  SubgraphLoopOptions loops;
  // What ranks the pairs in the loop check (pair_trust.hpp). kDistinctiveShare: a twin edge
  // matches only the repeated structure, whose features the views of every copy match; a true edge
  // also matches the unique texture. Measured over all connecting edges of a pair, against the
  // edges inside the subgraphs: books (photos) twin pair 0.63, true 0.69–0.90; street (photos)
  // twins 0.52–0.61, true and mixed 0.81–0.91; synthetic courtyard twins ≤ 0.55, true ≥ 0.66
  // (docs/pruning.md).
  PairTrustMeasure link_trust = PairTrustMeasure::kDistinctiveShare;
  // kDistinctiveShare of a pair whose RANSAC kept k edges, pulled toward the share of all its
  // connecting edges as if m of them had been kept too: (k·kept + m·all) / (k + m). 0 = off (the
  // paper ranks no pairs). Why: the share of one or two edges is the noisiest, and a
  // single distinctive edge outranked a true consensus of many (street,
  // seed 7, street configuration: a pair with no true edge, 0.70, above a 28-edge true one, 0.61;
  // docs/pruning.md).
  double trust_prior_edges = 2.0;
  int num_threads = 1;  // subgraph pairs aligned in parallel (the result does not depend on it)
  // The pruning's decisions reviewed against the model solved from the pruned graph, then adjusted
  // again (off by default, not in the paper; applied by PruneAndAudit, not PruneViewGraph).
  ModelEdgeAuditOptions audit;
  // The kept edges between subgraphs lose the matches their subgraphs' landmarks contradict
  // (landmark_match_check.hpp; off when max_angle_deg is 0).
  LandmarkMatchCheckOptions landmark_check;
  // The kept edges between subgraphs judged by the landmarks they miss in the model solved from the
  // pruned graph, solved and judged again while edges go (missing_correspondence_check.hpp; applied
  // by PruneAndAudit, not PruneViewGraph).
  MissingCorrespondenceOptions missing_correspondences;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct SubgraphPairReport {
  int k1 = -1;  // indices into RecursivePartitionResult::accepted
  int k2 = -1;
  SubgraphAlignmentStatus status = SubgraphAlignmentStatus::kNoEdges;
  size_t num_edges = 0;
  size_t num_voting_edges = 0;
  size_t num_removed_edges = 0;
  double beta = 1.0;
  std::vector<AlignmentHypothesis> hypotheses;  // RANSAC candidates (SubgraphAlignmentResult)
  int selected_hypothesis = -1;
  // Loop check (pairs with a frame transform only): the transform k2 -> k1, the triangles the pair
  // is in before any rejection, and whether the check rejected the whole pair.
  bool has_frame_transform = false;
  Similarity3 k2_to_k1;
  size_t consistent_triangles = 0;
  size_t inconsistent_triangles = 0;
  bool rejected_by_loops = false;
  int rejected_by_cycle = -1;  // rejected by the longer-cycle pass: index into report cycles
  // The pair's trust (link_trust over the edges its RANSAC kept, or all its edges when it has no
  // transform) and, under Method::kTrustedForest, what the forest decided.
  double trust = 0.0;
  // Match coverage over the placed edges the trust was taken on, relative to the edges inside the
  // subgraphs (PairTrust::RelativeCoverageOf); -1 when not measured.
  double coverage = -1.0;
  bool judged_by_forest = false;
  LinkDecision forest_decision = LinkDecision::kForest;
  // Its kept edges join capture neighbours (CaptureOrder; always false when the order is not used).
  bool capture_linked = false;
};

struct RemovedEdge {
  ViewPair pair{kUndefinedIndex, kUndefinedIndex};  // first < second
  int k1 = -1;
  int k2 = -1;
  InterSubgraphVerdict verdict = InterSubgraphVerdict::kConsistent;
  EdgeInvalidation invalidation;
};

struct ViewGraphPruningReport {
  // What the view graph says about the id order, and whether the pruning used it.
  CaptureOrderEvidence capture_order;
  // The capture path's rotation check before the partition (capture_path_rotations.hpp).
  CapturePathRotationCheck capture_path;
  // Then the direction check against the capture path's model (capture_path_directions.hpp).
  CapturePathDirectionCheck capture_path_directions;
  bool capture_order_used = false;
  RecursivePartitionResult partition;
  std::vector<SubgraphPairReport> pairs;  // connected pairs only, (k1, k2) order
  std::vector<RemovedEdge> removed_edges;  // pair order, then (i, j) order; then the rotation check's and the audit's
  std::vector<SubgraphTriangle> triangles;  // loops of aligned pairs (subgraph_loop_consistency.hpp)
  std::vector<SubgraphCycle> cycles;        // longer cycles judged (subgraph_cycle_consistency.hpp)
  // PairTrust::ReferenceShare and ReferenceCoverage: the units of the pairs' trust (0 when the
  // measure does not use them).
  double reference_distinctive_share = 0.0;
  double reference_coverage = 0.0;
  size_t num_input_edges = 0;   // valid edges before pruning
  size_t num_output_edges = 0;  // valid edges after pruning
  // The model audit (ViewGraphPruningOptions::audit, RunPrunedGlobalEngine): every inter-subgraph
  // edge measured against the first solve, and what changed (the engine then solved again).
  std::vector<EdgeAgreement> audit;
  size_t audit_readmitted = 0;
  size_t audit_removed = 0;
  // The landmark check of the matches between aligned subgraphs (ViewGraphPruningOptions::landmark_check).
  LandmarkMatchCheckReport landmark_check;
  // The rounds of the missing-correspondence check (ViewGraphPruningOptions::missing_correspondences).
  std::vector<MissingCorrespondenceRound> missing_correspondence_rounds;
  std::vector<StageTiming> timings;  // "subgraph partition", "inter-subgraph pruning" (+ the audit's)
  double total_seconds = 0.0;
};

// The paper's method: every PruneSfM addition (docs/pruning.md, "PruneSfM's additions") switched
// off in `options`, the other fields left as they are (the paper's values are the defaults there).
// The additions: distinctiveness weights in the partition, bisection of unsplittable communities,
// the baseline-ratio test, the sample cap, enumerated samples, match-coverage selection, the
// rotation-only fallback, the loop check of subgraph pairs with its trust prior, the landmark
// check of matches and the model audit.
void ApplyPaperMethod(ViewGraphPruningOptions* options);

// Invalidates the inconsistent inter-subgraph edges of `graph`. Progress: "subgraph partition",
// then "inter-subgraph pruning" (pairs done / pairs). Throws std::invalid_argument when
// options.Check() does.
void PruneViewGraph(const ViewGraphPruningOptions& options, ViewGraph* graph, const SfmData& views_and_intrinsics,
                    const FeaturesPerView& features, ViewGraphPruningReport* report,
                    const ProgressCallback& progress = {});

struct PrunedGlobalEngineOptions {
  ViewGraphPruningOptions pruning;
  GlobalEngineOptions engine;  // final solve
  // Copies `seed` into the final solve, the partition's per-community engine and the Louvain and
  // RANSAC seeds (so one --seed drives everything); the communities and the subgraph pairs run on
  // `num_threads` workers (the result does not depend on it), the final solve's Ceres on
  // `solver_threads` (more than 1 changes the last digits from run to run).
  void SetSeedAndThreads(uint64_t seed, int num_threads, int solver_threads = 1);

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct PrunedGlobalEngineReport {
  ViewGraphPruningReport pruning;  // with the audit's changes (removed_edges, audit, timings)
  GlobalEngineReport engine;       // the last solve
};

// How far PruneAndAudit went.
enum class PrunedGlobalEngineStep {
  kPruned,              // PruneViewGraph only (the audit is off)
  kAuditModelFailed,    // the solve of the pruned graph failed (report->engine says why): no audit
  kAudited,             // audited, no edge changed: *model is the audit's model of *pruned
  kAuditedWithChanges,  // audited, edges re-admitted or removed: *model predates them
  kSolved,              // the missing-correspondence check removed nothing in its last round:
                        // *model is the final solve of *pruned
  kSolvedBeforeChanges,  // its last round removed edges: *model predates them (solve again)
};

// GLOBAL_PRUNED's whole pruning, the part `prunesfm prune` shares with the engine: PruneViewGraph
// on a copy of `graph` into *pruned, then, when the audit is on, the solve of the pruned graph
// into *model and the audit of the removed and kept edges against it (ModelEdgeAuditOptions);
// then, when the missing-correspondence check is on, its rounds: the final solve of *pruned into
// *model, the kept edges between subgraphs judged against it, those that miss the landmarks it
// predicts removed, and again (MissingCorrespondenceOptions). Throws std::invalid_argument when options.Check() does.
PrunedGlobalEngineStep PruneAndAudit(const PrunedGlobalEngineOptions& options, const ViewGraph& graph,
                                     const SfmData& views_and_intrinsics, const FeaturesPerView& features,
                                     ViewGraph* pruned, SfmData* model, PrunedGlobalEngineReport* report,
                                     const ProgressCallback& progress = {});

// GLOBAL_PRUNED: PruneAndAudit, then the final solve of the pruned graph (the audit's model
// refined, or solved again when the audit changed edges). `graph` is copied, not modified. Same
// output contract as RunGlobalEngine; throws as PruneAndAudit.
void RunPrunedGlobalEngine(const PrunedGlobalEngineOptions& options, const ViewGraph& graph,
                           const SfmData& views_and_intrinsics, const FeaturesPerView& features, SfmData* out,
                           PrunedGlobalEngineReport* report, const ProgressCallback& progress = {});

}  // namespace sfm_pruning
