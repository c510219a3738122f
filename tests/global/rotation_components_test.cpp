// The building blocks of rotation averaging: the spanning-tree initialisation, the residual
// convention, the sparse increment solver and the IRLS losses.
#include <gtest/gtest.h>

#include <cmath>

#include "global/rotation_test_scene.hpp"
#include "sfm_pruning/global/rotation_increment_solver.hpp"
#include "sfm_pruning/global/rotation_initialization.hpp"
#include "sfm_pruning/global/rotation_irls.hpp"
#include "sfm_pruning/global/rotation_problem.hpp"
#include "sfm_pruning/view_graph/spanning_tree.hpp"

namespace sfm_pruning {
namespace {

// The solver only reads the edge's endpoints.
RotationEdge Edge(size_t i, size_t j) { return {i, j, Eigen::Matrix3d::Identity()}; }

TEST(RotationsAlongSpanningTree, NoiseFreeTreeGivesTruthInTheRootFrame) {
  testing::RotationSceneOptions options;
  options.num_views = 40;
  const testing::RotationScene scene = testing::MakeRotationScene(options);
  const SpanningTree tree = MaximumSpanningTree(scene.graph);
  const std::map<IndexT, Eigen::Matrix3d> rotations = RotationsAlongSpanningTree(scene.graph, tree);
  ASSERT_EQ(rotations.size(), scene.truth.size());
  EXPECT_TRUE(rotations.at(tree.root).isIdentity(0.0));
  // World = the root's camera frame: R_i = R_true_i R_true_root^T.
  const Eigen::Matrix3d root_true = scene.truth.at(tree.root);
  for (const auto& [id, R] : rotations) {
    EXPECT_LT(LogSO3(R.transpose() * scene.truth.at(id) * root_true.transpose()).norm(), 1e-12)
        << "view " << id;
  }
}

TEST(RotationsAlongSpanningTree, EmptyTreeGivesNothing) {
  EXPECT_TRUE(RotationsAlongSpanningTree(ViewGraph{}, SpanningTree{}).empty());
}

TEST(RotationResiduals, AngleOfTheDisagreementInTheWorldFrame) {
  std::mt19937 rng(3);
  ViewGraph graph;
  const Eigen::Matrix3d R_a = testing::UniformRandomRotation(&rng);
  const Eigen::Matrix3d R_b = testing::UniformRandomRotation(&rng);
  const Eigen::Matrix3d error = testing::RandomRotationOfAngle(&rng, 0.3);
  // Edge 7 -> 4 given from 7 to 4, stored oriented 4 -> 7.
  graph.AddEdge(7, 4, {}, RelativePose(error * R_a * R_b.transpose(), Eigen::Vector3d::UnitX()));
  const RotationProblem problem = BuildRotationProblem(graph);
  ASSERT_EQ(problem.view_ids, (std::vector<IndexT>{4, 7}));
  ASSERT_EQ(problem.pairs, (std::vector<ViewPair>{{4, 7}}));
  const std::vector<Eigen::Matrix3d> rotations = DenseRotations(problem, {{7, R_b}, {4, R_a}});
  const std::vector<Eigen::Vector3d> residuals = RotationResiduals(problem, rotations);
  ASSERT_EQ(residuals.size(), 1u);
  EXPECT_NEAR(residuals[0].norm(), 0.3, 1e-12);
  // e = Log(R_j^T R_ij R_i) with i = 4, j = 7: correcting R_i <- R_i Exp(-e) cancels it.
  const std::vector<Eigen::Matrix3d> corrected = {R_a * ExpSO3(-residuals[0]), R_b};
  EXPECT_LT(RotationResiduals(problem, corrected)[0].norm(), 1e-12);
}

TEST(RotationIncrementSolver, TreeIsSolvedExactly) {
  // Path 0 - 1 - 2 - 3 with the gauge at 1: d_1 = 0, d_0 = -e_01, d_2 = e_12, d_3 = e_12 + e_23.
  const std::vector<RotationEdge> edges = {Edge(0, 1), Edge(1, 2), Edge(2, 3)};
  const std::vector<Eigen::Vector3d> targets = {{0.1, -0.2, 0.3}, {0.5, 0.0, -0.1}, {-0.3, 0.2, 0.2}};
  RotationIncrementSolver solver(4, edges, 1);
  const RotationIncrementSolution solution = solver.Solve({2.0, 5.0, 0.5}, targets);
  ASSERT_TRUE(solution.success);
  EXPECT_TRUE(solution.increments[1].isZero(0.0));
  EXPECT_LT((solution.increments[0] + targets[0]).norm(), 1e-9);
  EXPECT_LT((solution.increments[2] - targets[1]).norm(), 1e-9);
  EXPECT_LT((solution.increments[3] - targets[1] - targets[2]).norm(), 1e-9);
}

TEST(RotationIncrementSolver, TriangleIsTheWeightedLeastSquaresSolution) {
  // Triangle 0-1, 1-2, 0-2 (gauge 0), scalar per coordinate: minimise
  //   w01 (d1 - a)^2 + w12 (d2 - d1 - b)^2 + w02 (d2 - c)^2.
  // Normal equations: [w01 + w12, -w12; -w12, w12 + w02] [d1; d2] = [w01 a - w12 b; w12 b + w02 c].
  const double w01 = 1.0, w12 = 3.0, w02 = 0.25;
  const Eigen::Vector3d a(0.2, -0.1, 0.05), b(0.1, 0.3, -0.2), c(0.4, 0.1, 0.0);
  Eigen::Matrix2d normal;
  normal << w01 + w12, -w12, -w12, w12 + w02;
  Eigen::Matrix<double, 2, 3> rhs;
  rhs.row(0) = (w01 * a - w12 * b).transpose();
  rhs.row(1) = (w12 * b + w02 * c).transpose();
  const Eigen::Matrix<double, 2, 3> expected = normal.inverse() * rhs;

  RotationIncrementSolver solver(3, {Edge(0, 1), Edge(1, 2), Edge(0, 2)}, 0);
  const RotationIncrementSolution solution = solver.Solve({w01, w12, w02}, {a, b, c});
  ASSERT_TRUE(solution.success);
  EXPECT_TRUE(solution.increments[0].isZero(0.0));
  EXPECT_LT((solution.increments[1] - expected.row(0).transpose()).norm(), 1e-9);
  EXPECT_LT((solution.increments[2] - expected.row(1).transpose()).norm(), 1e-9);
}

// The exact factorisation (chosen for sparse factors) and incomplete-Cholesky CG (forced with a
// zero fill budget) solve the same system.
TEST(RotationIncrementSolver, DirectAndIterativeSolversAgree) {
  const testing::RotationSceneOptions scene_options = testing::SceneOptions(300, 3);
  const RotationProblem problem = BuildRotationProblem(testing::MakeRotationScene(scene_options).graph);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> uniform(0.01, 2.0);
  std::vector<double> weights;
  std::vector<Eigen::Vector3d> targets;
  for (size_t k = 0; k < problem.edges.size(); ++k) {
    weights.push_back(uniform(rng));
    targets.push_back(Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng)) -
                      Eigen::Vector3d::Constant(1.0));
  }
  RotationIncrementSolverOptions direct_options;
  direct_options.max_direct_factor_nonzeros_per_view = 1e9;
  RotationIncrementSolverOptions iterative_options;
  iterative_options.max_direct_factor_nonzeros_per_view = 0.0;
  RotationIncrementSolver direct(problem.view_ids.size(), problem.edges, 7, direct_options);
  RotationIncrementSolver iterative(problem.view_ids.size(), problem.edges, 7, iterative_options);
  const RotationIncrementSolution a = direct.Solve(weights, targets);
  const RotationIncrementSolution b = iterative.Solve(weights, targets);
  ASSERT_TRUE(a.success);
  ASSERT_TRUE(b.success);
  EXPECT_TRUE(a.used_direct_solver);
  EXPECT_FALSE(b.used_direct_solver);
  EXPECT_EQ(a.num_iterations, 0);
  EXPECT_GT(b.num_iterations, 0);
  EXPECT_LT(a.relative_residual, 1e-12);
  for (size_t k = 0; k < a.increments.size(); ++k) {
    EXPECT_LT((a.increments[k] - b.increments[k]).norm(), 1e-8) << k;
  }
  EXPECT_TRUE(a.increments[7].isZero(0.0));
  EXPECT_TRUE(b.increments[7].isZero(0.0));
}

// w(r) must be rho'(r) / r up to a constant factor (the IRLS majorisation); check it against a
// central difference of rho at residuals around the scale.
TEST(RotationLoss, WeightIsDerivativeOverResidual) {
  const double scale = 0.1;
  for (RotationLoss loss : {RotationLoss::kL1, RotationLoss::kGemanMcClure}) {
    // Normalising constant c = rho'(r) / (r w(r)), measured at one residual, then checked at all.
    auto ratio = [&](double r) {
      const double h = 1e-6;
      const double derivative =
          (RotationLossValue(loss, r + h, scale) - RotationLossValue(loss, r - h, scale)) / (2 * h);
      return derivative / (r * RotationLossWeight(loss, r, scale));
    };
    const double c = ratio(0.03);
    for (double r : {0.01, 0.05, 0.09, 0.2, 0.5, 1.0, 3.0}) {
      EXPECT_NEAR(ratio(r) / c, 1.0, 1e-5) << "loss " << static_cast<int>(loss) << " r " << r;
    }
  }
  // Geman-McClure: weight 1 at 0, 1/4 at the scale; L1: 1/r above the floor.
  EXPECT_DOUBLE_EQ(RotationLossWeight(RotationLoss::kGemanMcClure, 0.0, scale), 1.0);
  EXPECT_DOUBLE_EQ(RotationLossWeight(RotationLoss::kGemanMcClure, scale, scale), 0.25);
  EXPECT_DOUBLE_EQ(RotationLossWeight(RotationLoss::kL1, 0.5, scale), 2.0);
  EXPECT_DOUBLE_EQ(RotationLossWeight(RotationLoss::kL1, 0.0, scale), 10.0);
}

TEST(RefineRotationsIrls, ConvergesFromPerturbedStartOnNoiseFreeGraph) {
  const testing::RotationSceneOptions scene_options = testing::SceneOptions(60, 3);
  const testing::RotationScene scene = testing::MakeRotationScene(scene_options);
  const RotationProblem problem = BuildRotationProblem(scene.graph);
  std::vector<Eigen::Matrix3d> rotations = DenseRotations(problem, scene.truth);
  std::mt19937 rng(5);
  for (size_t k = 1; k < rotations.size(); ++k) {
    rotations[k] = rotations[k] * testing::RandomRotationOfAngle(&rng, DegToRad(10.0));
  }
  const RotationIrlsSummary summary = RefineRotationsIrls(problem, 0, RotationIrlsOptions{}, &rotations);
  ASSERT_FALSE(summary.failed) << summary.failure_reason;
  EXPECT_TRUE(summary.converged);
  EXPECT_LT(summary.final_cost, 1e-20);
  EXPECT_LT(summary.final_cost, summary.initial_cost);
  // View 0 was not perturbed and is the gauge, so no global alignment is needed.
  for (size_t k = 0; k < rotations.size(); ++k) {
    EXPECT_LT(RadToDeg(LogSO3(rotations[k].transpose() * scene.truth.at(problem.view_ids[k])).norm()), 1e-7);
  }
}

}  // namespace
}  // namespace sfm_pruning
