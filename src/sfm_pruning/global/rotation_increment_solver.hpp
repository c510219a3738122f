// One weighted least-squares step of rotation averaging: the tangent-space increments d_i that
// best satisfy d_j - d_i = e_ij over the edges (rotation_problem.hpp), with one weight per edge.
//
// Because the Jacobian is the incidence matrix times I_3 and the weights are scalars, the
// 3n x 3n normal equations are L (x) I_3, L the weighted graph Laplacian. We therefore solve
// the n x n sparse Laplacian once per coordinate (three right-hand sides), never a 3n x 3n
// system. The gauge (a global rotation) is fixed by d_gauge = 0, i.e. the gauge row and column
// are removed, which makes the reduced Laplacian positive definite on a connected graph.
//
// Solver: conjugate gradients preconditioned by an incomplete Cholesky factor (Eigen). A direct
// sparse Cholesky is exact but its fill-in explodes on the expander-like graphs of large
// unordered collections (random chords leave no small separators); incomplete Cholesky keeps
// the factor's memory at the matrix's, is exact on trees and chains (no fill), and CG is fast
// on well-connected graphs. Single-threaded and deterministic.
#pragma once

#include <cstddef>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/global/rotation_problem.hpp"

namespace sfm_pruning {

struct RotationIncrementSolverOptions {
  // CG stops when |L x - b| <= tolerance * |b| for each of the three coordinates.
  double relative_tolerance = 1e-10;
  // Per coordinate. Incomplete-Cholesky CG needs a few tens on typical view graphs.
  int max_iterations = 1000;
};

struct RotationIncrementSolution {
  bool success = false;  // false: preconditioner failure or CG did not reach the tolerance
  std::vector<Eigen::Vector3d> increments;  // d_i per dense index (d_gauge = 0)
  int num_iterations = 0;          // CG iterations, summed over the three coordinates
  double relative_residual = 0.0;  // the largest of the three
};

// Built once per problem: the Laplacian's sparsity pattern and the fill-reducing ordering of
// the preconditioner depend on the edges only, so successive IRLS steps (new weights, same
// edges) refill the values and refactorise without reordering.
class RotationIncrementSolver {
 public:
  // `edges` must connect all `num_views` views (else the system is singular and Solve fails).
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
