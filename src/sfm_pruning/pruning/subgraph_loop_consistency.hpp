// Loop consistency between subgraphs: the check across subgraph pairs that the per-pair RANSAC
// (subgraph_alignment.hpp) cannot make. PruneSfM's addition to the paper (docs/pruning.md).
//
// Why: the inter-subgraph RANSAC keeps the largest mutually consistent set of a pair's edges.
// Where every edge between two subgraphs is a doppelganger (books: the 42 edges between the two
// sides of the desk corner all see the other copy of the same textbooks) those edges agree with
// each other, form a perfect consensus and survive. What exposes them is a third subgraph: the
// frame transforms around a loop of subgraphs must compose to the identity, and the wrong
// transform breaks every loop it is part of while the right ones close.
//
// Each aligned pair (k1, k2) gives the similarity from k2's frame to k1's (scale β, rotation and
// translation of the selected RANSAC hypothesis: SubgraphAlignmentResult::k2_to_k1). For every
// triangle of aligned pairs (a, b, c) the loop S_ab · S_bc · S_ca is compared to the identity:
//   rotation: its angle, at most max_rotation_deg;
//   scale:    max(s, 1/s), at most max_scale_ratio;
//   translation: how far it moves a's mean camera centre, as a fraction of the triangle's mean
//             side length (distances between the three subgraph centres in a's frame, at least
//             a's own radius), at most max_translation_fraction.
// Rejection is greedy and deterministic (then a second pass over longer cycles,
// subgraph_cycle_consistency.hpp): while some pair lies in more inconsistent triangles than
// consistent ones, the pair with the largest (inconsistent − consistent) count is rejected (ties:
// the smaller support, then the later pair), and the triangles are counted again without it. A
// pair in no triangle cannot be judged (it is kept); a rejected pair always lies in a triangle
// whose two other pairs stay, so a rejection never disconnects the subgraphs.
#pragma once

#include <cstddef>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/sfm/similarity.hpp"

namespace sfm_pruning {

struct SubgraphLoopOptions {
  bool enabled = true;
  // kTriangleVote: the triangle vote, then the longer cycles (FindLoopInconsistentLinks, above).
  // kTrustedForest: every pair is judged against the most trusted spanning forest of the pairs
  // (trusted_link_forest.hpp); the vote needs the true transforms to be the majority of the
  // triangles, the forest only needs the trust to rank them first.
  enum class Method { kTriangleVote, kTrustedForest };
  Method method = Method::kTrustedForest;
  // kTrustedForest: a redundant pair that nothing can verify (no transform on its cycle) is kept
  // when its trust reaches this, cut below. The trust is the distinctive share of its inliers over
  // that of the edges inside the subgraphs (1 = as distinctive as those): measured, twin pairs
  // books 0.63, real street 0.52–0.61, courtyard ≤ 0.55, sequential_large median 0.66; true pairs
  // ≥ 0.66, 0.69, 0.81, and p10 0.75 on sequential_large, where cutting them all emptied the graph
  // (2,088 true edges of 7,157 cut; AUC@10 15.0 against GLOBAL's 23.7).
  double min_unverified_trust = 0.65;
  // ... and its match coverage (SubgraphPairLink::relative_coverage: of the landmarks its placed
  // views should see, how many its edges matched, over the same for the edges inside the
  // subgraphs) reaches this, when measured. sequential_large@1000: twin pairs median 0.51 absolute,
  // true pairs p10 0.69 (inside: ~0.8).
  double min_unverified_coverage = 0.75;
  // kTrustedForest: a redundant pair without a transform of its own whose forest path has a pair
  // without one too is judged by its edges against the transform chained along the shortest path
  // of verified pairs between its subgraphs, where one exists (trusted_link_forest.hpp), instead of
  // by its trust alone.
  bool verify_along_verified_paths = true;
  // kTrustedForest: pairs of fewer connecting edges enter Kruskal's order after all the others (the
  // inter-subgraph RANSAC's min_edges_for_ransac: below it a pair has no majority of its own).
  size_t min_edges_for_trust = 3;
  // Measured on books (real images): the closing triangle turns by 1.6–3.1° and moves a's centre
  // by 0.08–0.15 of its side, the triangles through the doppelganger pair by 53–55° and 1.4–1.5.
  // The scale of a pair is the least certain part of its transform (it comes from the spread of
  // the chained translations): a closing triangle's scale drifted to 1.42, hence the loose bound.
  double max_rotation_deg = 5.0;
  double max_scale_ratio = 2.0;
  double max_translation_fraction = 0.25;
  // Second pass, cycles of 4..max_cycle_length subgraphs (subgraph_cycle_consistency.hpp); below 4
  // the pass is off.
  size_t max_cycle_length = 6;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

// A subgraph's mean camera centre and radius (median distance of its centres to the mean), in its
// own frame: the translation error's reference length.
struct SubgraphFrame {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double radius = 0.0;
};

// One aligned subgraph pair: k1 < k2, X_k1 = k2_to_k1(X_k2); support = consensus edges;
// trust = how much the pair's selected edges look like true ones (ViewGraphPruningOptions::
// link_trust: the match coverage of the selected hypothesis, infinity when nothing was expected,
// which is no evidence against the pair; or the distinctive share of its inliers).
struct SubgraphLink {
  int k1 = -1;
  int k2 = -1;
  Similarity3 k2_to_k1;
  size_t support = 0;
  double trust = std::numeric_limits<double>::infinity();
};

// Is link a more trusted than link b: the higher trust, then the larger support? (The loop
// passes cut the less trusted of two links they cannot tell apart otherwise.)
bool MoreTrustedLink(const SubgraphLink& a, const SubgraphLink& b);

struct SubgraphTriangle {
  int a = -1, b = -1, c = -1;  // a < b < c, subgraph indices
  double rotation_deg = 0.0;
  double scale_ratio = 1.0;
  double translation_fraction = 0.0;
  bool consistent = true;
};

// A cycle of four or more subgraphs judged by the second pass (subgraph_cycle_consistency.hpp).
struct SubgraphCycle {
  std::vector<int> subgraphs;  // c0 -> c1 -> ... -> c(l-1) -> c0
  double rotation_deg = 0.0;
  double scale_ratio = 1.0;
  double translation_fraction = 0.0;
  size_t loop_factor = 1;  // ⌊(l − 1) / 2⌋: the triangle bounds are widened by it
  bool consistent = true;
};

struct RejectedLink {
  size_t link = 0;  // index into the links given
  size_t inconsistent_triangles = 0;  // at the time of rejection
  size_t consistent_triangles = 0;
  int cycle = -1;  // the second pass: index into SubgraphLoopResult::cycles of the broken cycle
};

struct SubgraphLoopResult {
  std::vector<SubgraphTriangle> triangles;  // every triangle of the input links, (a, b, c) order
  // Per input link, the triangles it is in before any rejection.
  std::vector<size_t> consistent_triangles;
  std::vector<size_t> inconsistent_triangles;
  std::vector<SubgraphCycle> cycles;      // the cycles the second pass judged, in order
  std::vector<RejectedLink> rejected;  // in rejection order
};

// The loop of a triangle a < b < c from its three links (a, b), (b, c), (a, c).
SubgraphTriangle MeasureSubgraphTriangle(int a, int b, int c, const Similarity3& b_to_a, const Similarity3& c_to_b,
                                         const Similarity3& c_to_a, const SubgraphFrame& frame_a,
                                         const SubgraphFrame& frame_b, const SubgraphFrame& frame_c,
                                         const SubgraphLoopOptions& options);

// `frames` is indexed by subgraph; every link's k1, k2 must index it.
SubgraphLoopResult FindLoopInconsistentLinks(const std::vector<SubgraphLink>& links,
                                             const std::vector<SubgraphFrame>& frames,
                                             const SubgraphLoopOptions& options = {});

}  // namespace sfm_pruning
