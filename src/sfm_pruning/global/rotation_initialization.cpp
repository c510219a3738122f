#include "sfm_pruning/global/rotation_initialization.hpp"

namespace sfm_pruning {

std::map<IndexT, Eigen::Matrix3d> RotationsAlongSpanningTree(const ViewGraph& graph,
                                                             const SpanningTree& tree) {
  std::map<IndexT, Eigen::Matrix3d> rotations;
  // bfs_order lists every parent before its children, so one pass suffices.
  for (IndexT view : tree.bfs_order) {
    const IndexT parent = tree.parent.at(view);
    if (parent == view) {
      rotations[view] = Eigen::Matrix3d::Identity();
      continue;
    }
    rotations[view] = graph.OrientedRelativePose(parent, view).rotation * rotations.at(parent);
  }
  return rotations;
}

}  // namespace sfm_pruning
