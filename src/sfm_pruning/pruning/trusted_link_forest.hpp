// Which pairs of subgraphs keep their connecting edges, decided against the most trusted spanning
// forest (SubgraphLoopOptions::Method::kTrustedForest; PruneSfM's addition to the paper,
// docs/pruning.md, "The trusted forest").
//
// Why not a vote: the triangle vote (subgraph_loop_consistency.hpp) needs the true transforms
// to be the majority of the triangles. Where the repeated structure is seen from many places (a
// street of identical facades, four alike walls) the twin transforms are the majority and close
// triangles among themselves: the fold is a consistent world too. What tells the two worlds apart
// is not consistency but evidence a twin cannot fake: the trust of a pair (the distinctiveness of
// its inliers, or its match coverage) ranks the true pairs first.
//
// Kruskal's order, most trusted pair first among the pairs of at least min_edges_for_trust
// connecting edges, then among the others.
// (The trust of one or two edges is the noisiest, and such a pair seldom has a transform: in the
// forest it leaves every cycle through it unverifiable. castle-P19 lost a 16-edge true pair that
// way to a one-edge pair of trust 1.49.)
//   - a pair joining two groups of subgraphs not yet connected is a forest pair: kept (with the
//     edges its RANSAC kept; a pair without a transform keeps all its edges, nothing says which
//     of them are wrong);
//   - a pair whose subgraphs are already connected closes a cycle with the forest path between
//     them. With a transform, and transforms all along that path, the cycle is measured
//     (MeasureSubgraphCycle: the triangle bounds widened by the paper's loop factor) and the pair
//     is kept when it closes, cut when it breaks. Otherwise nothing can verify it: being redundant
//     it is cut unless its own trust and its match coverage vouch for it (min_unverified_trust,
//     min_unverified_coverage).
// The forest never changes once built, so every pair is judged once against more trusted ones,
// and no cut ever disconnects what the pairs connected.
#pragma once

#include <cstddef>
#include <vector>

#include "sfm_pruning/pruning/subgraph_loop_consistency.hpp"
#include "sfm_pruning/sfm/similarity.hpp"

namespace sfm_pruning {

struct SubgraphPairLink {
  int k1 = -1;  // subgraph indices into the frames
  int k2 = -1;
  bool has_transform = false;  // an aligned pair with a non-empty consensus
  Similarity3 k2_to_k1;        // X_k1 = k2_to_k1(X_k2), when has_transform
  double trust = 0.0;
  size_t support = 0;  // edges the pair keeps; breaks ties of trust (more first)
  double relative_coverage = -1.0;  // PairTrust::RelativeCoverageOf; negative: not measured
  size_t num_edges = 0;             // connecting edges of the pair, kept or not
};

enum class LinkDecision {
  kForest,               // kept: joins two groups of subgraphs
  kClosesCycle,          // kept: its cycle with the forest closes
  kBreaksCycle,          // cut: its cycle with the forest does not close
  kRedundantUnverified,  // cut: redundant, no transform along its cycle to verify it with, and its
                         // trust below SubgraphLoopOptions::min_unverified_trust or its measured
                         // coverage below min_unverified_coverage
  kKeptUnverified,       // kept: redundant and unverifiable, but trusted that much
};

// "forest", "closes_cycle", "breaks_cycle", "redundant_unverified", "kept_unverified".
const char* LinkDecisionName(LinkDecision decision);

struct TrustedForestResult {
  std::vector<LinkDecision> decisions;  // per input pair
  std::vector<int> cycle_of;            // per input pair: index into cycles, -1 if not measured
  std::vector<SubgraphCycle> cycles;    // in the order measured
};

TrustedForestResult SelectLinksByTrustedForest(const std::vector<SubgraphPairLink>& pairs,
                                               const std::vector<SubgraphFrame>& frames,
                                               const SubgraphLoopOptions& options);

}  // namespace sfm_pruning
