// The scale β (k2 units -> k1 units) that one connecting edge <i, j> alone implies, from depths
// (PruneSfM's addition to the paper; docs/pruning.md, "One edge's own scale").
//
// Why: the paper's β* comes from the spread of the chained translations of several edges
// (chained_relative_pose.hpp), so a set of edges that all land on the same view j carries no
// scale and no hypothesis can be made from it. On a street of identical facades that is exactly
// the true evidence of a thin stretch: the two or three true edges between a subgraph and the next
// land on its first view, while a dozen agreeing twin edges spread over all its views and win
// every vote. One edge does carry a scale: a feature f of j matched to i is an observation of a
// landmark of k1 (through i) and often of a landmark of k2 (through j's own subgraph), and the
// distance of those two points from j's centre, in each frame, differ by β:
//   β_e = median over such features of |X^k1 − C_j^k1| / |X^k2 − C_j^k2|
// with C_j^k1 the centre of j as the edge's PnP placed it. Empty with fewer than
// min_correspondences such features.
#pragma once

#include <cstddef>
#include <map>
#include <optional>

#include "sfm_pruning/pruning/subgraph_solution.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

std::optional<double> EdgeDepthScale(const ViewGraph& graph, IndexT view_i, IndexT view_j, const SubgraphSolution& k1,
                                     const std::map<ObservationKey, IndexT>& landmarks_k1, const Pose& pose_j_in_k1,
                                     const SubgraphSolution& k2, const std::map<ObservationKey, IndexT>& landmarks_k2,
                                     size_t min_correspondences = 8);

}  // namespace sfm_pruning
