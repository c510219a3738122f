#include <algorithm>
#include <map>
#include <optional>

#include <gtest/gtest.h>

#include "pruning/pruning_test_scene.hpp"
#include "sfm_pruning/geometry/so3.hpp"
#include "sfm_pruning/pruning/chained_relative_pose.hpp"
#include "sfm_pruning/pruning/subgraph_alignment.hpp"

namespace sfm_pruning {
namespace {

using testing::MakePruningTestScene;
using testing::PruningTestScene;
using testing::RandomSimilarity;
using testing::Similarity;

const std::vector<IndexT> kViewsK1 = {0, 1, 2, 3, 4, 5, 6, 7};
const std::vector<IndexT> kViewsK2 = {8, 9, 10, 11, 12, 13, 14, 15};
constexpr double kScaleK1 = 2.5;
constexpr double kScaleK2 = 0.4;
constexpr double kTrueBeta = kScaleK1 / kScaleK2;  // k2 units -> k1 units

// Two subgraphs of eight views, each in its own similarity frame, joined by 10 true edges and
// 4 edges that matched a twin of the structure (rotated by 25° and shifted).
struct TwoSubgraphs {
  PruningTestScene scene = MakePruningTestScene(16, 50, 11);
  Similarity frame_k1 = RandomSimilarity(1, kScaleK1);
  Similarity frame_k2 = RandomSimilarity(2, kScaleK2);
  SubgraphSolution k1;
  SubgraphSolution k2;
  std::vector<ViewPair> true_edges = {{0, 8}, {1, 9}, {2, 10}, {3, 11}, {4, 12},
                                      {5, 13}, {6, 14}, {7, 15}, {0, 9}, {1, 10}};
  std::vector<ViewPair> twin_edges = {{2, 8}, {3, 9}, {4, 14}, {5, 15}};

  explicit TwoSubgraphs(bool with_twins = true) {
    for (const ViewPair& edge : true_edges) scene.AddExactEdge(edge.first, edge.second);
    if (with_twins) {
      Similarity twin;
      twin.rotation = ExpSO3(DegToRad(25.0) * Eigen::Vector3d::UnitZ());
      twin.translation = Eigen::Vector3d(0.3, 0.2, 0.0);
      for (const ViewPair& edge : twin_edges) scene.AddTwinEdge(edge.first, edge.second, twin);
    }
    k1 = scene.Solution(kViewsK1, frame_k1);
    k2 = scene.Solution(kViewsK2, frame_k2);
  }
  SubgraphAlignmentResult Align(const SubgraphAlignmentOptions& options = {}) const {
    return AlignSubgraphPair(scene.graph, k1, k2, scene.views_and_intrinsics, scene.features, options);
  }
};

TEST(ChainedRelativePose, ClosedFormScaleRecoversTheTrueScale) {
  TwoSubgraphs setup(false);
  const Pose mean_k1 = SubgraphMeanPose(setup.k1);
  const Pose mean_k2 = SubgraphMeanPose(setup.k2);
  std::vector<ChainedRelativePose> chains;
  for (const ViewPair& edge : setup.true_edges) {
    const Pose j_in_k1 = setup.frame_k1.Apply(setup.scene.poses[edge.second]);  // exact placement
    chains.push_back(ChainRelativePose(mean_k1, j_in_k1, setup.k2.poses.at(edge.second), mean_k2));
  }
  const std::optional<double> beta = SolveChainScale(chains);
  ASSERT_TRUE(beta.has_value());
  EXPECT_NEAR(*beta, kTrueBeta, 1e-9);
  // With β* every edge gives the same c1 -> c2 pose: the true relative pose of the mean cameras.
  for (const ChainedRelativePose& chain : chains) {
    EXPECT_LT((chain.Translation(*beta) - chains[0].Translation(*beta)).norm(), 1e-9);
    EXPECT_LT(RotationAngleBetween(chain.rotation, chains[0].rotation), 1e-9);
  }
  // One edge, or edges that all share j, carry no scale information.
  EXPECT_FALSE(SolveChainScale({chains[0]}).has_value());
  EXPECT_FALSE(SolveChainScale({chains[0], chains[0]}).has_value());
}

TEST(SubgraphAlignment, ExactEdgesAreAllKeptAndTheScaleIsRecovered) {
  TwoSubgraphs setup(false);
  const SubgraphAlignmentResult result = setup.Align();
  ASSERT_EQ(result.status, SubgraphAlignmentStatus::kAligned);
  EXPECT_EQ(result.num_voting_edges, 10u);
  EXPECT_EQ(result.sample_size, 4u);
  EXPECT_NEAR(result.beta, kTrueBeta, 1e-4);
  EXPECT_TRUE(result.RemovedEdges().empty());
  for (const auto& decision : result.edges) {
    EXPECT_EQ(decision.placement.status, EdgePlacementStatus::kPlaced);
    EXPECT_EQ(decision.placement.num_correspondences, 50u);
    EXPECT_EQ(decision.verdict, InterSubgraphVerdict::kConsistent);
    EXPECT_LT(decision.rotation_deviation_deg, 1e-3);
  }
  // The frame transform of the hypothesis is the true one: k1's frame ∘ k2's frame⁻¹.
  const Similarity3 truth = setup.frame_k1.Compose(setup.frame_k2.Inverse());
  EXPECT_EQ(result.consensus_size, 10u);
  EXPECT_NEAR(result.k2_to_k1.scale, truth.scale, 1e-4);
  EXPECT_LT(RotationAngleBetween(result.k2_to_k1.rotation, truth.rotation), 1e-6);
  for (const Eigen::Vector3d& X : setup.scene.points) {
    EXPECT_LT((result.k2_to_k1.Apply(setup.frame_k2.Apply(X)) - setup.frame_k1.Apply(X)).norm(), 1e-4);
  }
}

TEST(SubgraphAlignment, RansacRemovesEdgesToTheTwinStructure) {
  TwoSubgraphs setup;
  const SubgraphAlignmentResult result = setup.Align();
  ASSERT_EQ(result.status, SubgraphAlignmentStatus::kAligned);
  EXPECT_EQ(result.num_voting_edges, 14u);
  EXPECT_EQ(result.sample_size, 5u);  // floor(0.4 · 14)
  EXPECT_NEAR(result.beta, kTrueBeta, 1e-4);
  std::vector<ViewPair> expected_kept = setup.true_edges;
  std::sort(expected_kept.begin(), expected_kept.end());
  std::vector<ViewPair> expected_removed = setup.twin_edges;
  std::sort(expected_removed.begin(), expected_removed.end());
  EXPECT_EQ(result.KeptEdges(), expected_kept);
  EXPECT_EQ(result.RemovedEdges(), expected_removed);
  SubgraphAlignmentOptions options;
  for (const auto& decision : result.edges) {
    if (decision.kept) continue;
    EXPECT_EQ(decision.verdict, InterSubgraphVerdict::kRotationDeviation);
    EXPECT_GT(decision.rotation_deviation_deg, 5.0);
    const EdgeInvalidation why = InterSubgraphInvalidation(decision, options);
    EXPECT_EQ(why.reason, EdgeInvalidReason::kInterSubgraphInconsistent);
    EXPECT_DOUBLE_EQ(why.value, decision.rotation_deviation_deg);
    EXPECT_DOUBLE_EQ(why.threshold, 5.0);
  }
}

// Five true edges and ten twin edges between two arcs of eight views. A true edge matches the first
// `true_points` landmarks of i (all when 0), a twin edge `twin_points` of them on a copy of the
// structure turned 90° about z.
struct OutnumberedTrueEdges {
  PruningTestScene scene = MakePruningTestScene(16, 60, 11);
  const std::vector<ViewPair> true_edges = {{5, 8}, {6, 8}, {7, 8}, {6, 9}, {7, 9}};  // 11°–34° apart
  // View v sits at 11.25°·v on the arc; the copy is the structure turned 90° about z, so PnP
  // puts j of a twin edge (i, j) 90° back along the arc, next to i.
  const std::vector<ViewPair> twin_edges = {{0, 8}, {1, 9},  {2, 10}, {3, 11}, {4, 12},
                                            {5, 13}, {6, 14}, {7, 15}, {0, 9}, {1, 10}};
  SubgraphSolution k1;
  SubgraphSolution k2;

  OutnumberedTrueEdges(size_t true_points, size_t twin_points) {
    for (const ViewPair& edge : true_edges) scene.AddExactEdge(edge.first, edge.second, true_points);
    Similarity twin;
    twin.rotation = ExpSO3(DegToRad(90.0) * Eigen::Vector3d::UnitZ());
    for (const ViewPair& edge : twin_edges) scene.AddTwinEdge(edge.first, edge.second, twin, twin_points);
    k1 = scene.Solution(kViewsK1, RandomSimilarity(1, kScaleK1));
    k2 = scene.Solution(kViewsK2, RandomSimilarity(2, kScaleK2));
  }
  static std::vector<ViewPair> Sorted(std::vector<ViewPair> edges) {
    std::sort(edges.begin(), edges.end());
    return edges;
  }
  SubgraphAlignmentResult Align(const SubgraphAlignmentOptions& options) const {
    return AlignSubgraphPair(scene.graph, k1, k2, scene.views_and_intrinsics, scene.features, options);
  }
};

// Twin edges outnumber the true ones but match only the copied third of the structure: the
// paper's largest consensus keeps the twins, the match coverage keeps the true edges.
TEST(SubgraphAlignment, MatchCoverageKeepsTrueEdgesOutnumberedByTwinEdges) {
  const OutnumberedTrueEdges pair(0, 20);
  const std::vector<ViewPair>& true_edges = pair.true_edges;
  const std::vector<ViewPair> sorted_true = OutnumberedTrueEdges::Sorted(pair.true_edges);
  const std::vector<ViewPair> sorted_twins = OutnumberedTrueEdges::Sorted(pair.twin_edges);

  // Samples of two edges: with 0.4 · 15 = 6 a clean sample is rare (the engine caps it too).
  SubgraphAlignmentOptions options;
  options.sample_fraction = 0.15;
  SubgraphAlignmentOptions paper = options;
  paper.hypothesis_selection = SubgraphAlignmentOptions::HypothesisSelection::kLargestConsensus;
  const SubgraphAlignmentResult largest = pair.Align(paper);
  ASSERT_EQ(largest.status, SubgraphAlignmentStatus::kAligned);
  EXPECT_EQ(largest.hypotheses.size(), 1u);
  EXPECT_EQ(largest.KeptEdges(), sorted_twins);
  EXPECT_EQ(largest.RemovedEdges(), sorted_true);

  const SubgraphAlignmentResult coverage = pair.Align(options);
  ASSERT_EQ(coverage.status, SubgraphAlignmentStatus::kAligned);
  EXPECT_EQ(coverage.KeptEdges(), sorted_true);
  EXPECT_EQ(coverage.RemovedEdges(), sorted_twins);
  EXPECT_NEAR(coverage.beta, kTrueBeta, 1e-4);
  ASSERT_EQ(coverage.hypotheses.size(), 2u);
  EXPECT_EQ(coverage.selected_hypothesis, 1);
  EXPECT_EQ(coverage.hypotheses[0].consensus_size, 10u);  // the twins, found first
  EXPECT_EQ(coverage.hypotheses[1].consensus_size, 5u);
  // A true edge matches every landmark its placed view sees; a twin edge at most the copied third.
  EXPECT_EQ(coverage.hypotheses[1].matched_landmarks, coverage.hypotheses[1].expected_landmarks);
  EXPECT_GT(coverage.hypotheses[1].expected_landmarks, 0u);
  EXPECT_EQ(3 * coverage.hypotheses[0].matched_landmarks, coverage.hypotheses[0].expected_landmarks);
  EXPECT_LT(coverage.hypotheses[0].coverage_score, 0.0);  // ruled out
  EXPECT_GT(coverage.hypotheses[1].coverage_score, 0.0);
  EXPECT_TRUE(coverage.hypotheses[0].ruled_out);
  EXPECT_FALSE(coverage.hypotheses[1].ruled_out);
  for (const auto& decision : coverage.edges) {
    const bool is_true = std::count(true_edges.begin(), true_edges.end(),
                                    ViewPair{decision.placement.view_i, decision.placement.view_j}) > 0;
    if (is_true) {
      EXPECT_EQ(decision.placement.num_matched_landmarks, decision.placement.num_expected_landmarks);
    } else {
      EXPECT_EQ(decision.verdict, InterSubgraphVerdict::kRotationDeviation);
    }
  }
}

// Real images: true edges re-detect under half of what they should see, so both candidates fall
// below the break-even. The pair's candidates are then compared with each other: the twins match
// 12 of the 60 landmarks next to i, under half the true edges' share, and are ruled out.
TEST(SubgraphAlignment, BelowTheBreakEvenTheCandidatesAreComparedWithEachOther) {
  const OutnumberedTrueEdges pair(25, 12);
  SubgraphAlignmentOptions options;
  options.sample_fraction = 0.15;
  const SubgraphAlignmentResult relative = pair.Align(options);
  ASSERT_EQ(relative.status, SubgraphAlignmentStatus::kAligned);
  ASSERT_EQ(relative.hypotheses.size(), 2u);
  EXPECT_EQ(relative.hypotheses[0].consensus_size, 10u);  // the twins
  EXPECT_EQ(relative.hypotheses[1].consensus_size, 5u);
  EXPECT_LT(relative.hypotheses[0].coverage_score, 0.0);
  EXPECT_LT(relative.hypotheses[1].coverage_score, 0.0);
  EXPECT_NEAR(relative.hypotheses[0].Coverage(), 12.0 / 60.0, 1e-12);
  EXPECT_LT(relative.hypotheses[0].Coverage(), 0.5 * relative.hypotheses[1].Coverage());
  EXPECT_EQ(relative.selected_hypothesis, 1);
  EXPECT_EQ(relative.KeptEdges(), OutnumberedTrueEdges::Sorted(pair.true_edges));

  options.relative_coverage_break_even = 0.0;  // the largest of all wins
  const SubgraphAlignmentResult largest = pair.Align(options);
  EXPECT_EQ(largest.selected_hypothesis, 0);
  EXPECT_EQ(largest.KeptEdges(), OutnumberedTrueEdges::Sorted(pair.twin_edges));
}

TEST(SubgraphAlignment, SameSeedSameDecisions) {
  TwoSubgraphs setup;
  SubgraphAlignmentOptions options;
  options.seed = 1234;
  const SubgraphAlignmentResult first = setup.Align(options);
  const SubgraphAlignmentResult second = setup.Align(options);
  EXPECT_EQ(first.best_iteration, second.best_iteration);
  EXPECT_EQ(first.beta, second.beta);
  EXPECT_EQ(first.KeptEdges(), second.KeptEdges());
  ASSERT_EQ(first.edges.size(), second.edges.size());
  for (size_t k = 0; k < first.edges.size(); ++k) {
    EXPECT_EQ(first.edges[k].rotation_deviation_deg, second.edges[k].rotation_deviation_deg);
    EXPECT_EQ(first.edges[k].translation_deviation, second.edges[k].translation_deviation);
  }
}

TEST(SubgraphAlignment, EdgeWithTooFewCorrespondencesDoesNotVote) {
  TwoSubgraphs setup(false);
  setup.scene.AddExactEdge(6, 8, 5);  // 5 matches < 12
  SubgraphAlignmentResult result = setup.Align();
  ASSERT_EQ(result.status, SubgraphAlignmentStatus::kAligned);
  EXPECT_EQ(result.num_voting_edges, 10u);
  const auto weak = std::find_if(result.edges.begin(), result.edges.end(), [](const auto& d) {
    return d.placement.view_i == 6 && d.placement.view_j == 8;
  });
  ASSERT_NE(weak, result.edges.end());
  EXPECT_EQ(weak->placement.status, EdgePlacementStatus::kTooFewCorrespondences);
  EXPECT_EQ(weak->placement.num_correspondences, 5u);
  EXPECT_FALSE(weak->voted);
  EXPECT_EQ(weak->verdict, InterSubgraphVerdict::kCannotVote);
  EXPECT_TRUE(weak->kept);  // default policy

  SubgraphAlignmentOptions remove;
  remove.non_voting_edges = SubgraphAlignmentOptions::NonVotingPolicy::kRemove;
  result = setup.Align(remove);
  EXPECT_EQ(result.RemovedEdges(), std::vector<ViewPair>({{6, 8}}));
  const EdgeInvalidation why = InterSubgraphInvalidation(result.edges[std::distance(
      result.edges.begin(), std::find_if(result.edges.begin(), result.edges.end(),
                                         [](const auto& d) { return !d.kept; }))], remove);
  EXPECT_EQ(why.reason, EdgeInvalidReason::kOther);
  EXPECT_DOUBLE_EQ(why.value, 5.0);
  EXPECT_DOUBLE_EQ(why.threshold, 12.0);
}

TEST(SubgraphAlignment, WithoutScaleTheRotationsAloneSeparateATwinThatTurns) {
  // Every connecting edge lands on view 8: no sample carries scale information (β needs two
  // different views j), so no hypothesis is valid. The chained rotations still agree for the four
  // true edges and differ by 25° for the two twins.
  PruningTestScene scene = MakePruningTestScene(16, 50, 11);
  for (IndexT i : {0u, 1u, 2u, 3u}) scene.AddExactEdge(i, 8);
  Similarity twin;
  twin.rotation = ExpSO3(DegToRad(25.0) * Eigen::Vector3d::UnitZ());
  twin.translation = Eigen::Vector3d(0.3, 0.2, 0.0);
  for (IndexT i : {4u, 5u}) scene.AddTwinEdge(i, 8, twin);
  const SubgraphSolution k1 = scene.Solution(kViewsK1, RandomSimilarity(1, kScaleK1));
  const SubgraphSolution k2 = scene.Solution(kViewsK2, RandomSimilarity(2, kScaleK2));
  SubgraphAlignmentResult result = AlignSubgraphPair(scene.graph, k1, k2, scene.views_and_intrinsics, scene.features);
  ASSERT_EQ(result.status, SubgraphAlignmentStatus::kRotationOnly);
  EXPECT_FALSE(result.has_frame_transform);
  EXPECT_EQ(result.consensus_size, 4u);
  EXPECT_EQ(result.KeptEdges(), std::vector<ViewPair>({{0, 8}, {1, 8}, {2, 8}, {3, 8}}));
  EXPECT_EQ(result.RemovedEdges(), std::vector<ViewPair>({{4, 8}, {5, 8}}));
  for (const InterSubgraphEdgeDecision& decision : result.edges) {
    if (decision.kept) continue;
    EXPECT_EQ(decision.verdict, InterSubgraphVerdict::kRotationDeviation);
    EXPECT_NEAR(decision.rotation_deviation_deg, 25.0, 0.5);
  }
  SubgraphAlignmentOptions paper;
  paper.rotation_only_fallback = false;
  result = AlignSubgraphPair(scene.graph, k1, k2, scene.views_and_intrinsics, scene.features, paper);
  EXPECT_EQ(result.status, SubgraphAlignmentStatus::kNoValidHypothesis);
  EXPECT_EQ(result.KeptEdges().size(), 6u);
}

TEST(SubgraphAlignment, PairsWithFewEdgesFollowTheirPolicy) {
  PruningTestScene scene = MakePruningTestScene(16, 50, 11);
  scene.AddExactEdge(0, 8);
  scene.AddExactEdge(1, 9);
  const SubgraphSolution k1 = scene.Solution(kViewsK1, RandomSimilarity(1, 1.0));
  const SubgraphSolution k2 = scene.Solution(kViewsK2, RandomSimilarity(2, 3.0));
  SubgraphAlignmentResult result = AlignSubgraphPair(scene.graph, k1, k2, scene.views_and_intrinsics, scene.features);
  EXPECT_EQ(result.status, SubgraphAlignmentStatus::kTooFewVotingEdges);
  EXPECT_EQ(result.KeptEdges().size(), 2u);
  EXPECT_EQ(result.edges[0].verdict, InterSubgraphVerdict::kFewEdges);
  SubgraphAlignmentOptions remove;
  remove.few_edges = SubgraphAlignmentOptions::FewEdgesPolicy::kRemoveAll;
  result = AlignSubgraphPair(scene.graph, k1, k2, scene.views_and_intrinsics, scene.features, remove);
  EXPECT_EQ(result.RemovedEdges().size(), 2u);
  // Unconnected subgraphs.
  const SubgraphSolution lone = scene.Solution({12}, Similarity());
  EXPECT_EQ(AlignSubgraphPair(scene.graph, k1, lone, scene.views_and_intrinsics, scene.features).status,
            SubgraphAlignmentStatus::kNoEdges);
}

// A transform found elsewhere (the trusted forest's chained transform) judges the edges of a pair
// that could not judge them itself: the true edges agree with the true transform, the twin edges
// with the transform of the twin, and an edge that did not vote agrees with nothing.
TEST(SubgraphAlignment, EdgesAreJudgedAgainstAGivenTransform) {
  TwoSubgraphs setup;
  const SubgraphAlignmentResult result = setup.Align();
  const Similarity3 truth = setup.frame_k1.Compose(setup.frame_k2.Inverse());
  const SubgraphAlignmentOptions options;
  const std::vector<EdgeAgainstTransform> judged =
      JudgeEdgesAgainstTransform(result, setup.k1, setup.k2, truth, options);
  ASSERT_EQ(judged.size(), result.edges.size());
  const auto is_twin = [&](const InterSubgraphEdgeDecision& decision) {
    const ViewPair edge{decision.placement.view_i, decision.placement.view_j};
    return std::find(setup.twin_edges.begin(), setup.twin_edges.end(), edge) != setup.twin_edges.end();
  };
  for (size_t e = 0; e < result.edges.size(); ++e) {
    EXPECT_TRUE(judged[e].voted);
    EXPECT_EQ(judged[e].agrees, !is_twin(result.edges[e])) << e;
    if (is_twin(result.edges[e])) {
      EXPECT_GT(judged[e].rotation_deviation_deg, 20.0);  // the twin turns by 25°
    } else {
      EXPECT_LT(judged[e].rotation_deviation_deg, 1e-3);
      EXPECT_LT(judged[e].translation_deviation_fraction, 1e-3);
    }
  }

  // The twin's copy of k2 (structure turned 25° about z and shifted), seen through k2's frame.
  Similarity3 twin;
  twin.rotation = ExpSO3(DegToRad(25.0) * Eigen::Vector3d::UnitZ());
  twin.translation = Eigen::Vector3d(0.3, 0.2, 0.0);
  const Similarity3 twin_transform = setup.frame_k1.Compose(twin.Inverse()).Compose(setup.frame_k2.Inverse());
  const std::vector<EdgeAgainstTransform> against_twin =
      JudgeEdgesAgainstTransform(result, setup.k1, setup.k2, twin_transform, options);
  size_t true_agreeing = 0;
  for (size_t e = 0; e < result.edges.size(); ++e) {
    if (!is_twin(result.edges[e]) && against_twin[e].agrees) ++true_agreeing;
  }
  EXPECT_EQ(true_agreeing, 0u);

  SubgraphAlignmentResult not_voting = result;
  for (InterSubgraphEdgeDecision& decision : not_voting.edges) decision.voted = false;
  for (const EdgeAgainstTransform& edge : JudgeEdgesAgainstTransform(not_voting, setup.k1, setup.k2, truth, options)) {
    EXPECT_FALSE(edge.voted);
    EXPECT_FALSE(edge.agrees);
  }
}

}  // namespace
}  // namespace sfm_pruning
