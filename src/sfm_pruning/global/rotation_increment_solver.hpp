// One weighted least-squares step of rotation averaging: the tangent-space increments d_i that
// best satisfy d_j - d_i = e_ij over the edges (rotation_problem.hpp), with one weight per edge.
//
// Because the Jacobian is the incidence matrix times I_3 and the weights are scalars, the
// 3n x 3n normal equations are L (x) I_3, L the weighted graph Laplacian. We therefore solve
// the n x n sparse Laplacian once per coordinate (three right-hand sides), never a 3n x 3n
// system. The gauge (a global rotation) is fixed by d_gauge = 0, i.e. the gauge row and column
// are removed, which makes the reduced Laplacian positive definite on a connected graph.
//
// Solver, chosen per problem from the symbolic factorisation (edges only, not weights):
//   - exact sparse LDL^T (Eigen SimplicialLDLT, AMD ordering) when its factor stays small, which
//     is the case for chain- and band-like graphs (video, sequential captures). There an
//     incomplete factor is a poor preconditioner: the Laplacian's condition number grows like
//     n^2, and dropping even a few fill entries costs CG hundreds of iterations;
//   - otherwise conjugate gradients preconditioned by an incomplete Cholesky factor (Eigen,
//     natural ordering, memory of the order of the matrix). The expander-like graphs of large
//     unordered collections (random chords, no small separators) make the exact factor nearly
//     dense, but they are well conditioned, so CG needs only a few tens of iterations.
// Single-threaded and deterministic.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <memory>
#include <vector>

#include "sfm_pruning/global/rotation_problem.hpp"

namespace sfm_pruning {

struct RotationIncrementSolverOptions {
  // Use the exact factorisation when its factor has at most this many non-zeros per view
  // (a band of width b has about b). 0 = always conjugate gradients.
  double max_direct_factor_nonzeros_per_view = 50.0;
  // Conjugate gradients stop when |L x - b| <= tolerance * |b| for each of the three coordinates.
  double relative_tolerance = 1e-10;
  // Per coordinate. Incomplete-Cholesky CG needs a few tens on typical view graphs.
  int max_iterations = 1000;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct RotationIncrementSolution {
  bool success = false;  // false: preconditioner failure, CG missed the tolerance, non-finite
  std::vector<Eigen::Vector3d> increments;  // d_i per dense index (d_gauge = 0)
  bool used_direct_solver = false;
  int num_iterations = 0;          // CG iterations, summed over the three coordinates (0 direct)
  double relative_residual = 0.0;  // the largest of the three
};

// Built once per problem: the Laplacian's sparsity pattern and the fill-reducing ordering of
// the preconditioner depend on the edges only, so successive IRLS steps (new weights, same
// edges) refill the values and refactorise without reordering.
class RotationIncrementSolver {
 public:
  // `edges` must connect all `num_views` views (one connected component), otherwise the
  // problem is not defined (the gauge fixes only the gauge view's component).
  RotationIncrementSolver(size_t num_views, std::vector<RotationEdge> edges, size_t gauge_index,
                          const RotationIncrementSolverOptions& options = {});
  ~RotationIncrementSolver();
  RotationIncrementSolver(const RotationIncrementSolver&) = delete;
  RotationIncrementSolver& operator=(const RotationIncrementSolver&) = delete;

  // Minimises sum_k weights[k] |d_j - d_i - targets[k]|^2 with d_gauge = 0. `weights` (> 0) and
  // `targets` (e_ij) are parallel to the edges.
  RotationIncrementSolution Solve(const std::vector<double>& weights,
                                  const std::vector<Eigen::Vector3d>& targets);

 private:
  struct Impl;  // keeps Eigen's sparse and iterative solver headers out of this one
  std::unique_ptr<Impl> impl_;
};

}  // namespace sfm_pruning
