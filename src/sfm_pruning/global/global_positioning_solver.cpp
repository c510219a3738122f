#include "sfm_pruning/global/global_positioning_solver.hpp"

#include "sfm_pruning/util/option_checks.hpp"

#include <algorithm>
#include <memory>
#include <numeric>
#include <random>

#include <ceres/ceres.h>

#include "sfm_pruning/sfm/pose.hpp"

namespace sfm_pruning {
namespace {

// r = v - s (p_target - p_origin). Linear in each block, so the Jacobians are written out:
// dr/dp_origin = s I, dr/dp_target = -s I, dr/ds = -(p_target - p_origin).
class RayAlignmentCost : public ceres::SizedCostFunction<3, 3, 3, 1> {
 public:
  explicit RayAlignmentCost(const Eigen::Vector3d& ray) : ray_(ray) {}

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const Eigen::Map<const Eigen::Vector3d> origin(parameters[0]);
    const Eigen::Map<const Eigen::Vector3d> target(parameters[1]);
    const double scale = parameters[2][0];
    const Eigen::Vector3d offset = target - origin;
    Eigen::Map<Eigen::Vector3d> residual(residuals);
    residual = ray_ - scale * offset;
    if (jacobians == nullptr) return true;
    using RowMajor33 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;
    if (jacobians[0] != nullptr) {
      Eigen::Map<RowMajor33> d_origin(jacobians[0]);
      d_origin = scale * RowMajor33::Identity();
    }
    if (jacobians[1] != nullptr) {
      Eigen::Map<RowMajor33> d_target(jacobians[1]);
      d_target = -scale * RowMajor33::Identity();
    }
    if (jacobians[2] != nullptr) {
      Eigen::Map<Eigen::Vector3d> d_scale(jacobians[2]);
      d_scale = -offset;
    }
    return true;
  }

 private:
  Eigen::Vector3d ray_;
};

class ProgressReporter : public ceres::IterationCallback {
 public:
  ProgressReporter(const ProgressCallback& callback, const std::string& stage, int max_iterations)
      : callback_(callback), stage_(stage), max_iterations_(max_iterations) {}

  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    ReportProgress(callback_, stage_, static_cast<size_t>(summary.iteration), static_cast<size_t>(max_iterations_));
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const ProgressCallback& callback_;
  std::string stage_;
  int max_iterations_;
};

// One Ceres solve over the given constraints.
// With `warm_start` the positions are a solution (or nearly one) and the scales start at their
// optimum; from a random start they start at 1.
ceres::Solver::Summary SolveOnce(const PositioningSolverOptions& options, const std::vector<RayConstraint>& constraints,
                                 size_t fixed_position, const std::string& stage, bool warm_start,
                                 int max_num_iterations, std::vector<Eigen::Vector3d>* positions) {
  // From a random start every scale is 1 (a scale clamped at its bound would mute its constraint,
  // see min_ray_scale). From a solution each starts at its optimum v . d / |d|^2, so that the
  // re-solve begins at the previous cost instead of undoing the scales.
  std::vector<double> scales(constraints.size(), 1.0);
  for (size_t k = 0; warm_start && k < constraints.size(); ++k) {
    const Eigen::Vector3d offset = (*positions)[constraints[k].target] - (*positions)[constraints[k].origin];
    const double squared_norm = offset.squaredNorm();
    if (squared_norm > 0.0) scales[k] = std::max(options.min_ray_scale, constraints[k].ray.dot(offset) / squared_norm);
  }

  ceres::Problem problem;
  // One loss object shared by every residual; the problem deletes it once.
  ceres::LossFunction* loss = options.huber_scale > 0.0 ? new ceres::HuberLoss(options.huber_scale) : nullptr;
  for (size_t k = 0; k < constraints.size(); ++k) {
    double* origin = (*positions)[constraints[k].origin].data();
    double* target = (*positions)[constraints[k].target].data();
    problem.AddResidualBlock(new RayAlignmentCost(constraints[k].ray), loss, origin, target, &scales[k]);
    problem.SetParameterLowerBound(&scales[k], 0, options.min_ray_scale);
  }
  double* fixed = (*positions)[fixed_position].data();
  if (problem.HasParameterBlock(fixed)) problem.SetParameterBlockConstant(fixed);

  ceres::Solver::Options solver_options;
  // Not the Schur complement of bundle adjustment: points and scales share every residual, so
  // they cannot be eliminated together. Eliminating the points leaves each track's scales densely
  // coupled (4-5x slower, measured); eliminating the scales leaves the (centre, point) normal
  // equations, which is what sparse Cholesky on the whole system factorises anyway, with its own
  // fill-reducing order, and without Schur's overhead (1.5-2x faster, measured on 30 cameras,
  // 800 points, 14k observations).
  solver_options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  // Eigen's simplicial LDL^T, not CHOLMOD. CHOLMOD picks a supernodal factorisation once its flop
  // count per factor entry reaches 40, and this matrix sits right at that switch: one supernode
  // per scale, a few entries each, so the per-supernode overhead (BLAS calls, OpenMP regions,
  // workspace) dominates. On sequential_large@500 the solve from the random start (116k
  // unknowns, 41 flops per entry: supernodal) took 0.45 s per factorisation against 0.09 s for
  // the re-solve with 3 % fewer rays (35 flops per entry: simplicial), and Eigen's simplicial
  // factorisation takes 0.09 s for both.
  solver_options.sparse_linear_algebra_library_type = ceres::EIGEN_SPARSE;
  solver_options.max_num_iterations = max_num_iterations;
  solver_options.function_tolerance = options.function_tolerance;
  solver_options.gradient_tolerance = options.gradient_tolerance;
  solver_options.parameter_tolerance = options.parameter_tolerance;
  solver_options.num_threads = options.num_threads;
  solver_options.logging_type = ceres::SILENT;
  solver_options.minimizer_progress_to_stdout = false;
  ProgressReporter reporter(options.progress, stage, max_num_iterations);
  if (options.progress) solver_options.callbacks.push_back(&reporter);

  ceres::Solver::Summary ceres_summary;
  ceres::Solve(solver_options, &problem, &ceres_summary);
  return ceres_summary;
}

}  // namespace

std::vector<Eigen::Vector3d> RandomPositions(size_t count, double half_size, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(-half_size, half_size);
  std::vector<Eigen::Vector3d> positions(count);
  for (Eigen::Vector3d& p : positions) {
    // Explicit order: the evaluation order of three calls inside one constructor is unspecified.
    const double x = uniform(rng);
    const double y = uniform(rng);
    const double z = uniform(rng);
    p = Eigen::Vector3d(x, y, z);
  }
  return positions;
}

double RayConstraintResidualDeg(const RayConstraint& constraint, const std::vector<Eigen::Vector3d>& positions) {
  return RadToDeg(AngleBetweenVectors(constraint.ray, positions[constraint.target] - positions[constraint.origin]));
}

PositioningSolverSummary SolveRayAlignment(const PositioningSolverOptions& options,
                                           const std::vector<RayConstraint>& constraints, size_t fixed_position,
                                           const std::string& stage, std::vector<Eigen::Vector3d>* positions,
                                           bool from_solution) {
  PositioningSolverSummary summary;
  summary.rejected.assign(constraints.size(), false);
  if (constraints.empty()) {
    summary.termination = "no constraint";
    return summary;
  }
  std::vector<RayConstraint> kept = constraints;
  std::vector<size_t> kept_index(constraints.size());
  std::iota(kept_index.begin(), kept_index.end(), size_t{0});
  for (int round = 0;; ++round) {
    const bool resolve = round > 0;
    const ceres::Solver::Summary ceres_summary =
        SolveOnce(options, kept, fixed_position, stage, resolve || from_solution,
                  resolve ? options.max_num_resolve_iterations : options.max_num_iterations, positions);
    if (summary.num_solves++ == 0) summary.initial_cost = ceres_summary.initial_cost;
    summary.usable = ceres_summary.IsSolutionUsable();
    summary.termination = ceres_summary.message;
    summary.num_iterations += static_cast<int>(ceres_summary.iterations.size());
    summary.final_cost = ceres_summary.final_cost;
    if (!summary.usable || round >= options.num_rejection_rounds) break;

    std::vector<RayConstraint> consistent;
    std::vector<size_t> consistent_index;
    for (size_t k = 0; k < kept.size(); ++k) {
      if (RayConstraintResidualDeg(kept[k], *positions) <= options.rejection_threshold_deg) {
        consistent.push_back(kept[k]);
        consistent_index.push_back(kept_index[k]);
      }
    }
    if (consistent.size() == kept.size() || consistent.empty()) break;
    kept = std::move(consistent);
    kept_index = std::move(consistent_index);
  }
  std::vector<bool> is_kept(constraints.size(), false);
  for (const size_t k : kept_index) is_kept[k] = true;
  for (size_t k = 0; k < constraints.size(); ++k) summary.rejected[k] = !is_kept[k];
  summary.num_rejected = constraints.size() - kept.size();
  return summary;
}

void PositioningSolverOptions::Check() const {
  // <= 0 means plain least squares, so any number is in range; only NaN is not.
  RequireNumber(huber_scale, "PositioningSolverOptions::huber_scale (<= 0: plain least squares)");
  // Strictly positive (see the header); a cube of size 0 starts every position at one point.
  RequirePositiveAtMost(min_ray_scale, 1e6, "PositioningSolverOptions::min_ray_scale");
  RequirePositiveAtMost(init_cube_half_size, 1e6, "PositioningSolverOptions::init_cube_half_size");
  RequireAtLeast(num_random_starts, 1, "PositioningSolverOptions::num_random_starts");
  // 0 screens no start; 0 rejection rounds leave one solve.
  RequireAtLeast(start_screening_iterations, 0, "PositioningSolverOptions::start_screening_iterations");
  RequireAtLeast(num_rejection_rounds, 0, "PositioningSolverOptions::num_rejection_rounds");
  RequirePositiveAtMost(rejection_threshold_deg, 180.0, "PositioningSolverOptions::rejection_threshold_deg");
  // Ceres' own bounds.
  RequireAtLeast(max_num_iterations, 0, "PositioningSolverOptions::max_num_iterations");
  RequireAtLeast(max_num_resolve_iterations, 0, "PositioningSolverOptions::max_num_resolve_iterations");
  RequireAtLeast(function_tolerance, 0.0, "PositioningSolverOptions::function_tolerance");
  RequireAtLeast(gradient_tolerance, 0.0, "PositioningSolverOptions::gradient_tolerance");
  RequireAtLeast(parameter_tolerance, 0.0, "PositioningSolverOptions::parameter_tolerance");
  RequireAtLeast(num_threads, 1, "PositioningSolverOptions::num_threads");
}

}  // namespace sfm_pruning
