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
// connecting edges, then among the others; within each, the capture-linked pairs first when the
// capture order is used (capture_order.hpp: the path the photos were taken along is the backbone
// the other pairs must agree with).
// (The trust of one or two edges is the noisiest, and such a pair seldom has a transform: in the
// forest it leaves every cycle through it unverifiable. castle-P19 lost a 16-edge true pair that
// way to a one-edge pair of trust 1.49.)
//   - a pair joining two groups of subgraphs not yet connected is a forest pair: kept (with the
//     edges its RANSAC kept; a pair without a transform keeps all its edges, nothing says which
//     of them are wrong);
//   - a pair whose subgraphs are already connected closes a cycle with the forest path between
//     them. With a transform, and transforms all along that path, the cycle is measured
//     (MeasureSubgraphCycle: the triangle bounds widened by the paper's loop factor) and the pair
//     is kept when it closes, cut when it breaks. Otherwise the forest cannot verify it: being
//     redundant it is cut unless its own trust and its match coverage vouch for it
//     (min_unverified_trust, min_unverified_coverage);
//   - then such pairs without a transform of their own are looked at again, against the shortest
//     path of verified pairs between their subgraphs (SubgraphLoopOptions::
//     verify_along_verified_paths): their edges, tested against the transform chained along it,
//     keep or cut them. On block loops of 300-500 views most redundant pairs are unverifiable
//     through the forest (one pair on the long forest path lacks a transform), and the trust alone
//     let twin pairs through (0.66-0.96 against the 0.65 bound).
// The forest never changes once built, so every pair is judged once against more trusted ones,
// and no cut ever disconnects what the pairs connected.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
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
  // Its kept edges join views taken one after the other (capture_order.hpp): such pairs rank
  // before the others.
  bool capture_linked = false;
};

enum class LinkDecision {
  kForest,               // kept: joins two groups of subgraphs
  kClosesCycle,          // kept: its cycle with the forest closes
  kBreaksCycle,          // cut: its cycle with the forest does not close
  kRedundantUnverified,  // cut: redundant, no transform along its cycle to verify it with, and its
                         // trust below SubgraphLoopOptions::min_unverified_trust or its measured
                         // coverage below min_unverified_coverage
  kKeptUnverified,       // kept: redundant and unverifiable, but trusted that much
  kAgreesWithForest,     // kept: unverifiable through the forest and no transform of its own, but
                         // its edges agree with the transform chained along a path of verified
                         // pairs (ForestTransformCheck); those that do not are removed
  kContradictsForest,    // cut: likewise, and none of its edges agrees
};

// "forest", "closes_cycle", "breaks_cycle", "redundant_unverified", "kept_unverified",
// "agrees_with_forest", "contradicts_forest".
const char* LinkDecisionName(LinkDecision decision);

struct TrustedForestResult {
  std::vector<LinkDecision> decisions;  // per input pair
  std::vector<int> cycle_of;            // per input pair: index into cycles, -1 if not measured
  std::vector<SubgraphCycle> cycles;    // in the order measured
};

// Judges the edges of a redundant pair without a transform of its own against the transform
// X_k1 = k2_to_k1(X_k2) chained along a path of verified pairs between its subgraphs
// (SubgraphLoopOptions::verify_along_verified_paths): true when at least one of them agrees, false
// when none does, empty when none of them can be checked (no edge voted). The edge thresholds widen
// by `loop_factor`, that of the cycle the pair closes with the path (as the cycle bounds do).
struct ChainedTransform {
  Similarity3 k2_to_k1;
  size_t loop_factor = 1;
};
using ForestTransformCheck = std::function<std::optional<bool>(size_t pair, const ChainedTransform& chained)>;

TrustedForestResult SelectLinksByTrustedForest(const std::vector<SubgraphPairLink>& pairs,
                                               const std::vector<SubgraphFrame>& frames,
                                               const SubgraphLoopOptions& options,
                                               const ForestTransformCheck& check_against_forest = {});

}  // namespace sfm_pruning
