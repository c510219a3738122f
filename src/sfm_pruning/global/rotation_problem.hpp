// The data rotation averaging iterates on: the views of one connected component at dense
// indices 0..n-1 and the measured relative rotations of its valid edges.
//
// Linearisation (used by every rotation_* file). Absolute rotations R_i are world -> camera and
// an edge measures R_ij ~ R_j R_i^T (sfm/pose.hpp). Its residual is the world-frame rotation
//   e_ij = Log(R_j^T R_ij R_i),            |e_ij| = angle between R_ij and R_j R_i^T,
// and the estimate is updated on the right, R_i <- R_i Exp(d_i). To first order the updated
// residual is e_ij + d_i - d_j, so one weighted least-squares step asks d_j - d_i = e_ij: the
// Jacobian is the graph's incidence matrix times I_3, the same for every rotation, which is what
// keeps the normal equations a scalar graph Laplacian (rotation_increment_solver.hpp).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <map>
#include <vector>

#include "sfm_pruning/sfm/types.hpp"
#include "sfm_pruning/view_graph/view_graph.hpp"

namespace sfm_pruning {

struct RotationEdge {
  size_t i = 0;                                                     // dense index of ViewPair::first
  size_t j = 0;                                                     // dense index of ViewPair::second
  Eigen::Matrix3d relative_rotation = Eigen::Matrix3d::Identity();  // R_ij: camera i -> camera j
};

struct RotationProblem {
  std::vector<IndexT> view_ids;     // dense index -> view id, increasing
  std::vector<ViewPair> pairs;      // one per edge, ViewPair order
  std::vector<RotationEdge> edges;  // parallel to `pairs`
};

// Every node of `graph` and its valid edges. Throws std::out_of_range if a valid edge touches
// a node outside the graph (not possible for a ViewGraph built through its API).
RotationProblem BuildRotationProblem(const ViewGraph& graph);

// Dense rotations of `problem` from a map by view id; throws std::out_of_range for a missing id.
std::vector<Eigen::Matrix3d> DenseRotations(const RotationProblem& problem,
                                            const std::map<IndexT, Eigen::Matrix3d>& rotations);

// The inverse of DenseRotations: view id -> rotation.
std::map<IndexT, Eigen::Matrix3d> RotationsById(const RotationProblem& problem,
                                                const std::vector<Eigen::Matrix3d>& rotations);

// e_ij of every edge (see above), parallel to problem.edges.
std::vector<Eigen::Vector3d> RotationResiduals(const RotationProblem& problem,
                                               const std::vector<Eigen::Matrix3d>& rotations);

}  // namespace sfm_pruning
