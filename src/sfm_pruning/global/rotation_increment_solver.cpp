#include "sfm_pruning/global/rotation_increment_solver.hpp"

#include "sfm_pruning/util/option_checks.hpp"

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <algorithm>
#include <utility>

namespace sfm_pruning {
namespace {

// SimplicialLDLT that reports the size of its factor after the symbolic analysis, before any
// numeric work (Eigen computes the column counts there but does not expose them).
class SizedLdlt : public Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> {
 public:
  Eigen::Index FactorNonZeros() const { return m_nonZerosPerCol.sum(); }
};

}  // namespace

struct RotationIncrementSolver::Impl {
  size_t num_views = 0;
  std::vector<RotationEdge> edges;
  size_t gauge = 0;
  Eigen::SparseMatrix<double> laplacian;  // reduced: the gauge's row and column removed
  bool use_direct = false;
  SizedLdlt ldlt;
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double>, Eigen::Lower | Eigen::Upper,
                           Eigen::IncompleteCholesky<double, Eigen::Lower, Eigen::NaturalOrdering<int>>>
      cg;

  bool IsGauge(size_t index) const { return index == gauge; }
  Eigen::Index Row(size_t index) const {
    return static_cast<Eigen::Index>(index < gauge ? index : index - 1);
  }

  // Calls add(row, col, sign) for the Laplacian entries of every edge (+ on the diagonal, -
  // off it) and rhs(row, sign) for its right-hand side rows (b_j += w e, b_i -= w e): the
  // normal equations of sum_k w_k |d_j - d_i - e_k|^2 without the gauge's (zero) unknowns.
  template <typename AddEntry, typename AddRhs>
  void ForEachEntry(size_t k, AddEntry&& add, AddRhs&& rhs) const {
    const RotationEdge& edge = edges[k];
    const bool has_i = !IsGauge(edge.i);
    const bool has_j = !IsGauge(edge.j);
    if (has_i) {
      add(Row(edge.i), Row(edge.i), 1.0);
      rhs(Row(edge.i), -1.0);
    }
    if (has_j) {
      add(Row(edge.j), Row(edge.j), 1.0);
      rhs(Row(edge.j), 1.0);
    }
    if (has_i && has_j) {
      add(Row(edge.i), Row(edge.j), -1.0);
      add(Row(edge.j), Row(edge.i), -1.0);
    }
  }
};

RotationIncrementSolver::RotationIncrementSolver(size_t num_views, std::vector<RotationEdge> edges,
                                                 size_t gauge_index,
                                                 const RotationIncrementSolverOptions& options)
    : impl_(std::make_unique<Impl>()) {
  impl_->num_views = num_views;
  impl_->edges = std::move(edges);
  impl_->gauge = gauge_index;
  if (num_views < 2) return;
  const auto size = static_cast<Eigen::Index>(num_views - 1);
  std::vector<Eigen::Triplet<double>> pattern;
  pattern.reserve(4 * impl_->edges.size());
  for (size_t k = 0; k < impl_->edges.size(); ++k) {
    impl_->ForEachEntry(
        k, [&pattern](Eigen::Index r, Eigen::Index c, double) { pattern.emplace_back(r, c, 1.0); },
        [](Eigen::Index, double) {});
  }
  impl_->laplacian.resize(size, size);
  impl_->laplacian.setFromTriplets(pattern.begin(), pattern.end());
  impl_->laplacian.makeCompressed();
  if (options.max_direct_factor_nonzeros_per_view > 0.0) {
    impl_->ldlt.analyzePattern(impl_->laplacian);
    impl_->use_direct = static_cast<double>(impl_->ldlt.FactorNonZeros()) <=
                        options.max_direct_factor_nonzeros_per_view * static_cast<double>(size);
  }
  if (!impl_->use_direct) {
    impl_->cg.setTolerance(options.relative_tolerance);
    impl_->cg.setMaxIterations(options.max_iterations);
    impl_->cg.analyzePattern(impl_->laplacian);
  }
}

RotationIncrementSolver::~RotationIncrementSolver() = default;

RotationIncrementSolution RotationIncrementSolver::Solve(const std::vector<double>& weights,
                                                         const std::vector<Eigen::Vector3d>& targets) {
  Impl& impl = *impl_;
  RotationIncrementSolution solution;
  solution.increments.assign(impl.num_views, Eigen::Vector3d::Zero());
  if (impl.num_views < 2) {
    solution.success = true;  // only the gauge: nothing to solve
    return solution;
  }

  // Same pattern as in the constructor, so coeffRef only finds (never inserts) entries.
  impl.laplacian.coeffs().setZero();
  Eigen::MatrixX3d rhs = Eigen::MatrixX3d::Zero(impl.laplacian.rows(), 3);
  for (size_t k = 0; k < impl.edges.size(); ++k) {
    const double w = weights[k];
    impl.ForEachEntry(
        k, [&](Eigen::Index r, Eigen::Index c, double sign) { impl.laplacian.coeffRef(r, c) += sign * w; },
        [&](Eigen::Index r, double sign) { rhs.row(r) += sign * w * targets[k].transpose(); });
  }
  Eigen::MatrixX3d x = Eigen::MatrixX3d::Zero(impl.laplacian.rows(), 3);
  solution.used_direct_solver = impl.use_direct;
  if (impl.use_direct) {
    impl.ldlt.factorize(impl.laplacian);
    if (impl.ldlt.info() != Eigen::Success) return solution;
    x = impl.ldlt.solve(rhs);
    solution.success = impl.ldlt.info() == Eigen::Success && x.allFinite();
    solution.relative_residual = rhs.norm() > 0.0 ? (impl.laplacian * x - rhs).norm() / rhs.norm() : 0.0;
  } else {
    impl.cg.factorize(impl.laplacian);
    if (impl.cg.info() != Eigen::Success) return solution;
    solution.success = true;
    for (int c = 0; c < 3; ++c) {
      if (rhs.col(c).squaredNorm() == 0.0) continue;  // x = 0; CG's relative test needs b != 0
      x.col(c) = impl.cg.solve(rhs.col(c));
      solution.num_iterations += static_cast<int>(impl.cg.iterations());
      solution.relative_residual = std::max(solution.relative_residual, impl.cg.error());
      if (impl.cg.info() != Eigen::Success || !x.col(c).allFinite()) solution.success = false;
    }
  }
  for (size_t index = 0; index < impl.num_views; ++index) {
    if (!impl.IsGauge(index)) solution.increments[index] = x.row(impl.Row(index)).transpose();
  }
  return solution;
}

void RotationIncrementSolverOptions::Check() const {
  // 0: always conjugate gradients.
  RequireAtLeast(max_direct_factor_nonzeros_per_view, 0.0,
                 "RotationIncrementSolverOptions::max_direct_factor_nonzeros_per_view");
  // Relative to |b|: 1 is already met by x = 0.
  RequirePositiveAtMost(relative_tolerance, 1.0, "RotationIncrementSolverOptions::relative_tolerance");
  RequireAtLeast(max_iterations, 1, "RotationIncrementSolverOptions::max_iterations");
}

}  // namespace sfm_pruning
