// The robust "ray alignment" problem behind both positioning methods:
//
//   minimise  sum_k  huber( | v_k - s_k (p_target(k) - p_origin(k)) |^2 ),   s_k >= min_ray_scale
//
// over positions p and one scale s_k per constraint, v_k a unit world-frame direction.
//   * Global positioning (GLOMAP, paper eq. 2): origin = camera centre c_i, target = point X_k,
//     v = the observation ray R_i^T b_ik.
//   * Translation averaging: origin = c_i, target = c_j, v = the edge direction of c_j - c_i.
// At the optimum over s the residual is the component of v orthogonal to p_target - p_origin,
// i.e. sin of the angular error: bounded by 1 and free of the unknown distances, which is what
// makes random initialisation work and outliers harmless.
//
// Gauge: the cost is invariant to translating all positions (3 dof), fixed by holding one
// position constant, and to scaling them by lambda with s -> s / lambda (1 dof). The scale is not
// fixed by a constraint: the Levenberg-Marquardt damping keeps steps out of that null direction,
// and the lower bound on s stops the scene from growing without bound. Collapsing the scene is
// not a way out either: p_target = p_origin leaves the whole |v| = 1 as residual.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/util/progress.hpp"

namespace sfm_pruning {

struct RayConstraint {
  size_t origin = 0;  // index into the positions
  size_t target = 0;
  Eigen::Vector3d ray = Eigen::Vector3d::UnitZ();  // unit
};

struct PositioningSolverOptions {
  // Huber scale of the residual norm, which is about the angular error in radians (0.1 ~ 5.7 deg,
  // GLOMAP's value): rays further off weigh linearly. <= 0: plain least squares.
  double huber_scale = 0.1;
  // Lower bound of the scales s_k. Strictly positive rather than 0: with s = 0 a constraint is
  // satisfied by nothing (residual |v| = 1 whatever the positions) and gives no gradient to the
  // positions, so a scale that hits 0 during the early, random-start iterations would switch its
  // observation off for good; 1e-3 allows distances up to 1000 times the initial cube.
  double min_ray_scale = 1e-3;
  // Positions start uniformly in [-half, half]^3 (std::mt19937_64 seeded with `seed`); the scales
  // start at 1, which matches a cube of size ~1.
  double init_cube_half_size = 1.0;
  uint64_t seed = 0;
  // Random starts tried by SolveFromRandomStart (global_positioning_scene.hpp); 1 = one solve from
  // `seed`. The problem is not convex: on scenes whose repeated structure pulls views onto one
  // another, a start can end in a folded minimum. Each start's result is scored by its rays that
  // agree with it (within rejection_threshold_deg), as RANSAC scores a model by its inliers.
  int num_random_starts = 1;
  // With several starts and n > 0: each start is solved for n iterations only (no rejection
  // round) and scored; the best is then solved to the end from there. The basin a start falls
  // into shows early (docs/global.md), so the starts after the first cost n iterations each
  // instead of a whole solve. 0 = every start solved to the end.
  int start_screening_iterations = 0;

  // Huber still lets gross outliers bias the solution. After a solve, constraints whose ray
  // misses p_target - p_origin by more than rejection_threshold_deg are dropped and the problem
  // is solved again from the current positions, num_rejection_rounds times (0: one solve).
  int num_rejection_rounds = 1;
  double rejection_threshold_deg = 5.0;

  int max_num_iterations = 200;  // the solve from the random start
  // Each re-solve after a rejection round starts from the previous solution.
  int max_num_resolve_iterations = 200;
  // Tight by default: from a random start the relative cost decrease stays large until the
  // solution is reached, and noise-free data should converge to its exact positions.
  double function_tolerance = 1e-10;
  double gradient_tolerance = 1e-12;
  double parameter_tolerance = 1e-10;
  // Threads for Ceres (capped by it at the hardware concurrency). 1 gives bitwise reproducible
  // results; with more, Ceres sums in scheduling order and the last bits can differ.
  int num_threads = 1;
  // Called after each Ceres iteration with (stage, iteration, max_num_iterations).
  ProgressCallback progress;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct PositioningSolverSummary {
  bool usable = false;      // Ceres returned a usable solution (every solve did)
  std::string termination;  // Ceres' message of the last solve
  int num_solves = 0;
  int num_iterations = 0;     // over all solves
  double initial_cost = 0.0;  // Ceres cost (0.5 * sum of robustified squared residuals), first solve
  double final_cost = 0.0;    // last solve, over the constraints kept
  std::vector<bool> rejected;  // per constraint: dropped by a rejection round
  size_t num_rejected = 0;
};

// Uniform random positions in [-half_size, half_size]^3, deterministic for a seed.
std::vector<Eigen::Vector3d> RandomPositions(size_t count, double half_size, uint64_t seed);

// Angle in degrees between a constraint's ray and p_target - p_origin.
double RayConstraintResidualDeg(const RayConstraint& constraint, const std::vector<Eigen::Vector3d>& positions);

// Solves the problem above in place: `positions` hold the initial values and receive the
// solution; positions[fixed_position] is held constant (the translation gauge). Positions that
// no constraint touches are left as they are. Sparse Cholesky (SuiteSparse) on the normal
// equations; see the .cpp for why not Schur. Rejection
// rounds stop early when nothing is rejected or everything would be.
// `stage` names the progress reports. `from_solution`: the positions are a partial solve's (a
// screened start, SolveFromRandomStart), so the scales start at their optimum, not at 1.
PositioningSolverSummary SolveRayAlignment(const PositioningSolverOptions& options,
                                           const std::vector<RayConstraint>& constraints, size_t fixed_position,
                                           const std::string& stage, std::vector<Eigen::Vector3d>* positions,
                                           bool from_solution = false);

}  // namespace sfm_pruning
