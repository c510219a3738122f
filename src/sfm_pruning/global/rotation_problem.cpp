#include "sfm_pruning/global/rotation_problem.hpp"

#include "sfm_pruning/geometry/so3.hpp"
#include "sfm_pruning/view_graph/dense_node_index.hpp"

namespace sfm_pruning {

RotationProblem BuildRotationProblem(const ViewGraph& graph) {
  const DenseNodeIndex index(graph);
  RotationProblem problem;
  problem.view_ids.assign(graph.Nodes().begin(), graph.Nodes().end());
  graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge& edge) {
    problem.pairs.push_back(pair);
    problem.edges.push_back(
        {index.IndexOf(pair.first), index.IndexOf(pair.second), edge.relative_pose.rotation});
  });
  return problem;
}

std::vector<Eigen::Matrix3d> DenseRotations(const RotationProblem& problem,
                                            const std::map<IndexT, Eigen::Matrix3d>& rotations) {
  std::vector<Eigen::Matrix3d> dense;
  dense.reserve(problem.view_ids.size());
  for (IndexT id : problem.view_ids) dense.push_back(rotations.at(id));
  return dense;
}

std::map<IndexT, Eigen::Matrix3d> RotationsById(const RotationProblem& problem,
                                                const std::vector<Eigen::Matrix3d>& rotations) {
  std::map<IndexT, Eigen::Matrix3d> by_id;
  for (size_t k = 0; k < problem.view_ids.size(); ++k)
    by_id.emplace_hint(by_id.end(), problem.view_ids[k], rotations[k]);
  return by_id;
}

std::vector<Eigen::Vector3d> RotationResiduals(const RotationProblem& problem,
                                               const std::vector<Eigen::Matrix3d>& rotations) {
  std::vector<Eigen::Vector3d> residuals;
  residuals.reserve(problem.edges.size());
  for (const RotationEdge& edge : problem.edges) {
    residuals.push_back(LogSO3(rotations[edge.j].transpose() * edge.relative_rotation * rotations[edge.i]));
  }
  return residuals;
}

}  // namespace sfm_pruning
