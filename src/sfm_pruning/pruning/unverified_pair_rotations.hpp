// Subgraph pairs that no cycle could verify, judged by rotation against the rest of the pruned graph
// (PruneSfM's addition to the paper; docs/pruning.md, "Unverified pairs against a rotation averaging").
//
// Why: the trusted forest keeps a redundant pair that no cycle of full transforms can verify when its
// trust and match coverage vouch for it (trusted_link_forest.hpp, kKeptUnverified). On a long loop
// with identical buildings (sequential_large@1000) that is where the false loop closures live: 62 of
// the 73 twin-dominated edges of the final graph, in 24 pairs whose trust and coverage overlap the
// true pairs'. A cycle through the forest cannot refute them either: it runs through 37–119
// subgraphs, and their chained frame rotations drift by as much as a false loop turns. A rotation
// averaging of the graph without those pairs does not drift that way (it uses every edge at once),
// and a false loop between two sides of a street turns by ~180° against it: the true unverified
// pairs' edges differ from it by a median of 1.8° (p90 19.7°), the twin ones by 168.8°.
//
// What it cannot see: a false loop one building along the same straight turns by nothing.
#pragma once

#include <vector>

#include "sfm_pruning/global/rotation_averaging.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

struct UnverifiedPairRotationOptions {
  // A pair whose edges' median rotation error exceeds this many degrees is cut; 0 = off.
  double max_median_error_deg = 0.0;
};

// For every group of edges (one unverified pair's kept edges each): the median over its valid edges
// of the angle between the edge's relative rotation and the one the averaged absolute rotations
// imply, where the rotations come from EstimateGlobalRotations on `graph` without any of the
// groups' edges. -1 for a group none of whose edges has both views estimated.
std::vector<double> MedianRotationErrorsAgainstTheRest(const ViewGraph& graph,
                                                       const std::vector<std::vector<ViewPair>>& groups,
                                                       const RotationAveragingOptions& options);

}  // namespace sfm_pruning
