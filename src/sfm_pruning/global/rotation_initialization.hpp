// Initial absolute rotations for rotation averaging (METHOD.md §2.1): walk the maximum spanning
// tree of the view graph (weights = inliers, view_graph/spanning_tree.hpp) from its root, whose
// rotation is the identity, composing the most reliable relative rotations first:
//   R_child = R_{parent -> child} R_parent.
// Errors on a tree edge propagate to the whole subtree below it; the robust refinement repairs
// that, the tree only has to put most views near the right answer.
#pragma once

#include <Eigen/Core>
#include <map>

#include "sfm_pruning/view_graph/spanning_tree.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

// Rotations (world -> camera, world = the root's camera frame) of the views that `tree` spans,
// with the relative rotations of `graph`'s tree edges. Empty for an empty tree.
// Throws std::out_of_range when a tree edge is not in `graph`.
std::map<IndexT, Eigen::Matrix3d> RotationsAlongSpanningTree(const ViewGraph& graph,
                                                             const SpanningTree& tree);

}  // namespace sfm_pruning
