#include "sfm_pruning/view_graph/spectral_bisection.hpp"

#include <algorithm>
#include <numeric>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/view_graph/dense_node_index.hpp"

namespace sfm_pruning {

std::pair<NodeGroup, NodeGroup> SpectralBisection(const ViewGraph& graph) {
  const DenseNodeIndex index(graph);
  const size_t n = index.size();
  if (n < 2) throw Error("spectral bisection needs at least two views, got " + std::to_string(n));
  bool weighted = false;
  graph.ForEachValidEdge([&](const ViewPair&, const ViewGraphEdge& edge) { weighted = weighted || edge.weight > 0.0; });
  const auto size = static_cast<Eigen::Index>(n);
  Eigen::MatrixXd laplacian = Eigen::MatrixXd::Zero(size, size);
  graph.ForEachValidEdge([&](const ViewPair& pair, const ViewGraphEdge& edge) {
    const auto a = static_cast<Eigen::Index>(index.IndexOf(pair.first));
    const auto b = static_cast<Eigen::Index>(index.IndexOf(pair.second));
    const double weight = weighted ? std::max(edge.weight, 0.0) : 1.0;
    laplacian(a, b) -= weight;
    laplacian(b, a) -= weight;
    laplacian(a, a) += weight;
    laplacian(b, b) += weight;
  });
  // Eigenvalues come in increasing order; column 0 is the constant vector (eigenvalue 0).
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(laplacian);
  Eigen::VectorXd fiedler = solver.eigenvectors().col(1);
  if (fiedler(0) > 0.0) fiedler = -fiedler;
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return fiedler(static_cast<Eigen::Index>(a)) < fiedler(static_cast<Eigen::Index>(b));
  });
  std::pair<NodeGroup, NodeGroup> halves;
  for (size_t k = 0; k < n; ++k) (k < n / 2 ? halves.first : halves.second).push_back(index.IdOf(order[k]));
  std::sort(halves.first.begin(), halves.first.end());
  std::sort(halves.second.begin(), halves.second.end());
  if (halves.second.front() < halves.first.front()) std::swap(halves.first, halves.second);
  return halves;
}

}  // namespace sfm_pruning
