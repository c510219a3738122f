// Robust refinement of absolute rotations by iteratively reweighted least squares (IRLS) on the
// linearised residuals of rotation_problem.hpp, in the Chatterjee–Govindu family:
// each iteration weighs every edge by its current residual, solves one weighted least-squares
// step (rotation_increment_solver.hpp), applies R_i <- R_i Exp(d_i) and relinearises.
//
// The weights are isotropic (one per edge, from |e_ij|) rather than per coordinate: the loss
// is then invariant to the choice of world frame, and the three coordinates share one
// Laplacian. With w = rho'(r) / r each step is a majorise-minimise step of sum_k rho(|e_k|),
// so the robust cost decreases up to linearisation error.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "sfm_pruning/global/rotation_increment_solver.hpp"
#include "sfm_pruning/global/rotation_problem.hpp"
#include "sfm_pruning/util/progress.hpp"

namespace sfm_pruning {

enum class RotationLoss {
  // rho(r) = r above the scale, quadratic below it (so a residual of 0 has a finite weight):
  // w = 1 / max(r, scale). The L1 / geodesic-median stage: no edge dominates, so whole
  // subtrees mis-initialised through an outlier tree edge are pulled back.
  kL1,
  // Geman-McClure, rho(r) = s^2 r^2 / (r^2 + s^2): w = (s^2 / (r^2 + s^2))^2 (w(0) = 1).
  // Redescending: edges far beyond s get (almost) no weight, so outliers stop biasing the
  // estimate. Needs a start inside the basin, hence the L1 stage first.
  kGemanMcClure,
};

// w(r) and rho(r) of `loss` at residual angle r >= 0 with scale s > 0 (both radians).
double RotationLossWeight(RotationLoss loss, double residual_rad, double scale_rad);
double RotationLossValue(RotationLoss loss, double residual_rad, double scale_rad);

struct RotationIrlsOptions {
  RotationLoss loss = RotationLoss::kGemanMcClure;
  double loss_scale_rad = 0.0872664626;  // 5 degrees
  int max_iterations = 100;
  // Converged once no rotation moves by more than this in one iteration...
  double convergence_tolerance_rad = 1e-8;
  // ... or once an iteration lowers the robust cost by less than this fraction (0: never).
  // Stages that only need to reach a basin use it to skip a slow sublinear tail.
  double min_relative_cost_decrease = 0.0;
  // The first step gives every edge weight 1 (plain least squares). For the L1 stage this is
  // essential: right after the spanning-tree initialisation the tree edges have residual 0, so
  // 1 / max(r, floor) would give an outlier tree edge the largest weight of all and the
  // iterations would cling to it (Weiszfeld's iteration started on a data point).
  bool uniform_first_step = false;
  RotationIncrementSolverOptions linear_solver;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct RotationIrlsSummary {
  int num_iterations = 0;
  bool converged = false;
  bool failed = false;         // the linear solve failed or produced non-finite rotations
  std::string failure_reason;  // empty unless failed
  double initial_cost = 0.0;   // sum_k rho(|e_k|) before the first iteration
  double final_cost = 0.0;     // after the last one
  double last_max_increment_rad = 0.0;
  int num_linear_solver_iterations = 0;
};

// Refines `rotations` (dense, problem.view_ids order) in place; the view at `gauge_index` does
// not move. Calls progress(stage, iteration, max_iterations) after each iteration.
// On failure `rotations` holds the last finite estimate. Throws std::invalid_argument when
// options.Check() does.
RotationIrlsSummary RefineRotationsIrls(const RotationProblem& problem, size_t gauge_index,
                                        const RotationIrlsOptions& options,
                                        std::vector<Eigen::Matrix3d>* rotations,
                                        const ProgressCallback& progress = {},
                                        const std::string& stage = "rotation averaging");

}  // namespace sfm_pruning
