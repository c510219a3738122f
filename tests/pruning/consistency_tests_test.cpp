#include <algorithm>

#include <gtest/gtest.h>

#include "pruning/pruning_test_scene.hpp"
#include "sfm_pruning/geometry/so3.hpp"
#include "sfm_pruning/pruning/consistency_tests.hpp"

namespace sfm_pruning {
namespace {

using testing::MakePruningTestScene;
using testing::PruningTestScene;
using testing::RandomSimilarity;

// Six views, every pair an exact edge: triangles and longer loops everywhere.
struct ConsistencyFixture {
  PruningTestScene scene = MakePruningTestScene(6, 20, 7);
  SubgraphSolution solution;
  ConsistencyFixture() {
    for (IndexT a = 0; a < 6; ++a) {
      for (IndexT b = a + 1; b < 6; ++b) scene.AddExactEdge(a, b);
    }
    solution = scene.Solution({0, 1, 2, 3, 4, 5}, RandomSimilarity(3, 0.37));
  }
  // Rotates the stored relative pose of (a, b) by `angle_deg` about a fixed axis.
  void PerturbRotation(IndexT a, IndexT b, double angle_deg) {
    RelativePose& pose = scene.graph.MutableEdge(a, b)->relative_pose;
    pose.rotation = ExpSO3(DegToRad(angle_deg) * Eigen::Vector3d(0.0, 0.6, 0.8)) * pose.rotation;
  }
};

size_t CountViolations(const ConsistencyReport& report, ConsistencyTest test) {
  size_t count = 0;
  for (const auto& violation : report.violations) count += violation.test == test ? 1 : 0;
  return count;
}

TEST(SubgraphConsistency, ExactSolutionIsConsistent) {
  ConsistencyFixture fixture;
  const ConsistencyReport report = TestSubgraphConsistency(fixture.scene.graph, fixture.solution);
  EXPECT_TRUE(report.consistent);
  EXPECT_TRUE(report.violations.empty());
  EXPECT_GT(report.loop_error.count, 0u);
  EXPECT_EQ(report.relative_rotation_error.count, 15u);
  EXPECT_EQ(report.relative_translation_error.count, 15u);
  EXPECT_LT(report.loop_error.max_deg, 1e-6);
  EXPECT_LT(report.relative_rotation_error.max_deg, 1e-6);
  EXPECT_LT(report.relative_translation_error.max_deg, 1e-6);
}

TEST(SubgraphConsistency, TwelveDegreeRotationErrorIsFlaggedOnItsEdge) {
  ConsistencyFixture fixture;
  fixture.PerturbRotation(1, 3, 12.0);
  ConsistencyTestOptions options;
  options.test_loops = false;
  const ConsistencyReport report = TestSubgraphConsistency(fixture.scene.graph, fixture.solution, options);
  EXPECT_FALSE(report.consistent);
  ASSERT_EQ(CountViolations(report, ConsistencyTest::kRelativeRotation), 1u);
  const ConsistencyViolation& violation = report.violations.front();
  EXPECT_EQ(violation.test, ConsistencyTest::kRelativeRotation);
  EXPECT_EQ(violation.edge, ViewPair(1, 3));
  EXPECT_NEAR(violation.value, 12.0, 1e-6);
  EXPECT_DOUBLE_EQ(violation.threshold, 10.0);
  EXPECT_NEAR(report.relative_rotation_error.max_deg, 12.0, 1e-6);
}

TEST(SubgraphConsistency, FlippedTranslationIsFlaggedOnItsEdge) {
  ConsistencyFixture fixture;
  fixture.scene.graph.MutableEdge(2, 4)->relative_pose.translation *= -1.0;
  const ConsistencyReport report = TestSubgraphConsistency(fixture.scene.graph, fixture.solution);
  EXPECT_FALSE(report.consistent);
  ASSERT_EQ(report.violations.size(), 1u);  // rotations, hence loops, are untouched
  EXPECT_EQ(report.violations[0].test, ConsistencyTest::kRelativeTranslation);
  EXPECT_EQ(report.violations[0].edge, ViewPair(2, 4));
  EXPECT_NEAR(report.violations[0].value, 180.0, 1e-6);
}

TEST(SubgraphConsistency, LoopErrorBelowTheEdgeThresholdFailsTheLoopTest) {
  ConsistencyFixture fixture;
  fixture.PerturbRotation(0, 5, 7.0);  // > 5° on every triangle through (0, 5), < 10° per edge
  const ConsistencyReport report = TestSubgraphConsistency(fixture.scene.graph, fixture.solution);
  EXPECT_FALSE(report.consistent);
  EXPECT_EQ(CountViolations(report, ConsistencyTest::kRelativeRotation), 0u);
  ASSERT_GT(CountViolations(report, ConsistencyTest::kLoop), 0u);
  for (const auto& violation : report.violations) {
    ASSERT_EQ(violation.test, ConsistencyTest::kLoop);
    EXPECT_NEAR(violation.value, 7.0, 1e-6);
    EXPECT_DOUBLE_EQ(violation.threshold, LoopRotationThresholdDeg(violation.loop.size()));
    const bool has_0 = std::count(violation.loop.begin(), violation.loop.end(), 0u) == 1;
    const bool has_5 = std::count(violation.loop.begin(), violation.loop.end(), 5u) == 1;
    EXPECT_TRUE(has_0 && has_5);
  }
  ConsistencyTestOptions no_loops;
  no_loops.test_loops = false;
  EXPECT_TRUE(TestSubgraphConsistency(fixture.scene.graph, fixture.solution, no_loops).consistent);
}

TEST(SubgraphConsistency, UnposedViewsAreCountedNotTested) {
  ConsistencyFixture fixture;
  fixture.solution.poses.erase(5);
  const ConsistencyReport report = TestSubgraphConsistency(fixture.scene.graph, fixture.solution);
  EXPECT_TRUE(report.consistent);
  EXPECT_EQ(report.num_unposed_edges, 5u);
  EXPECT_EQ(report.relative_rotation_error.count, 10u);
}

}  // namespace
}  // namespace sfm_pruning
