// The missing-correspondence check (missing_correspondence_check.hpp) on exact data: cameras on a
// half circle of radius 8 (8 views: 22.5° apart) around a cloud of radius 2, the model the ground
// truth itself, every landmark seen by every view unless a test says otherwise.
#include <gtest/gtest.h>

#include <cmath>

#include "pruning/pruning_test_scene.hpp"
#include "sfm_pruning/pruning/missing_correspondence_check.hpp"
#include "support/option_checks.hpp"

namespace sfm_pruning {
namespace {

using testing::GroundTruthModel;
using testing::MakePruningTestScene;
using testing::PruningTestScene;

constexpr size_t kPoints = 60;

TEST(MissingCorrespondences, NeighboursThatSeeEveryLandmarkObserveAllThatIsPredicted) {
  const PruningTestScene scene = MakePruningTestScene(8, kPoints, 7);
  const std::vector<EdgeObservedShare> shares = MeasureObservedShares(GroundTruthModel(scene), {{0, 1}, {0, 4}}, {});
  ASSERT_EQ(shares.size(), 2u);
  EXPECT_EQ(shares[0].pair, ViewPair(0, 1));
  EXPECT_EQ(shares[0].to_second.predicted, kPoints);
  EXPECT_EQ(shares[0].to_second.observed, kPoints);
  EXPECT_EQ(shares[0].to_first.predicted, kPoints);
  EXPECT_EQ(shares[0].to_first.observed, kPoints);
  EXPECT_DOUBLE_EQ(shares[0].Share(), 1.0);
  // 90° apart: beyond max_viewing_angle_deg, nothing is predicted (and the share is 0, not NaN).
  EXPECT_EQ(shares[1].MinPredicted(), 0u);
  EXPECT_EQ(shares[1].Share(), 0.0);
}

TEST(MissingCorrespondences, TheShareIsThatOfTheBetterDirection) {
  const PruningTestScene scene = MakePruningTestScene(8, kPoints, 7);
  SfmData model = GroundTruthModel(scene);
  // View 1 misses landmarks 0-19 of view 0: a one-sided miss (the prediction may be what failed).
  for (IndexT p = 0; p < 20; ++p) model.structure.at(p).observations.erase(1);
  std::vector<EdgeObservedShare> shares = MeasureObservedShares(model, {{0, 1}}, {});
  ASSERT_EQ(shares.size(), 1u);
  EXPECT_EQ(shares[0].to_second.predicted, kPoints);  // 0's landmarks in 1
  EXPECT_EQ(shares[0].to_second.observed, kPoints - 20);
  EXPECT_EQ(shares[0].to_first.predicted, kPoints - 20);  // 1's landmarks in 0: all observed
  EXPECT_DOUBLE_EQ(shares[0].to_first.Share(), 1.0);
  EXPECT_DOUBLE_EQ(shares[0].Share(), 1.0);
  // View 0 also misses landmarks 20-39 of view 1: both directions miss, as a misplaced pair does.
  for (IndexT p = 20; p < 40; ++p) model.structure.at(p).observations.erase(0);
  shares = MeasureObservedShares(model, {{0, 1}}, {});
  EXPECT_EQ(shares[0].to_second.predicted, kPoints - 20);  // 0 observes 0-19 and 40-59
  EXPECT_EQ(shares[0].to_second.observed, kPoints - 40);
  EXPECT_EQ(shares[0].to_first.predicted, kPoints - 20);   // 1 observes 20-59
  EXPECT_EQ(shares[0].to_first.observed, kPoints - 40);
  EXPECT_DOUBLE_EQ(shares[0].Share(), 0.5);
}

TEST(MissingCorrespondences, LandmarksSeenFromMoreThanTwiceTheDistanceAreNotPredicted) {
  // Two views on one axis looking along +z at a patch at z = 0: 10 and 4 units away (ratio 2.5),
  // where a detector does not find the same points.
  SfmData model;
  model.intrinsics[0] = CameraIntrinsics::Pinhole(1000, 1000, 800.0, 500.0, 500.0);
  for (IndexT v = 0; v < 2; ++v) {
    View view;
    view.id_view = view.id_pose = v;
    view.id_intrinsic = 0;
    model.views[v] = view;
    model.poses[v] = Pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.0, 0.0, v == 0 ? -10.0 : -4.0));
  }
  for (IndexT p = 0; p < 9; ++p) {
    Landmark landmark;
    landmark.X = Eigen::Vector3d(0.2 * (p % 3) - 0.2, 0.2 * (p / 3) - 0.2, 0.0);
    landmark.observations[0] = {Eigen::Vector2d::Zero(), p};
    landmark.observations[1] = {Eigen::Vector2d::Zero(), p};
    model.structure[p] = landmark;
  }
  MissingCorrespondenceOptions options;
  EXPECT_EQ(MeasureObservedShares(model, {{0, 1}}, options)[0].to_second.predicted, 0u);
  EXPECT_EQ(MeasureObservedShares(model, {{0, 1}}, options)[0].to_first.predicted, 0u);
  options.max_distance_ratio = 3.0;
  const EdgeObservedShare share = MeasureObservedShares(model, {{0, 1}}, options)[0];
  EXPECT_EQ(share.to_second.predicted, 9u);
  EXPECT_EQ(share.to_first.predicted, 9u);
  EXPECT_DOUBLE_EQ(share.Share(), 1.0);
}

TEST(MissingCorrespondences, EdgesWithAnUnposedViewAreNotMeasured) {
  const PruningTestScene scene = MakePruningTestScene(8, kPoints, 7);
  SfmData model = GroundTruthModel(scene);
  model.poses.erase(model.views.at(2).id_pose);
  const std::vector<EdgeObservedShare> shares = MeasureObservedShares(model, {{1, 2}, {2, 3}, {3, 4}}, {});
  ASSERT_EQ(shares.size(), 1u);
  EXPECT_EQ(shares[0].pair, ViewPair(3, 4));
}

// Twenty edges observing 66-74 % of 100 predicted landmarks, one at 40 %, one too small to judge.
std::vector<EdgeObservedShare> ScatteredShares() {
  std::vector<EdgeObservedShare> shares;
  const auto edge = [](IndexT first, size_t predicted, size_t observed) {
    const ObservedLandmarks direction{predicted, observed};
    return EdgeObservedShare{{first, first + 1}, direction, direction};
  };
  for (IndexT e = 0; e < 20; ++e) shares.push_back(edge(e, 100, 66 + (e % 5) * 2));
  shares.push_back(edge(30, 100, 40));
  shares.push_back(edge(40, 10, 0));
  return shares;
}

TEST(MissingCorrespondences, AnEdgeFarBelowTheSpreadOfTheOthersIsRemoved) {
  const MissingCorrespondenceRound round = JudgeObservedShares(ScatteredShares(), {});
  EXPECT_EQ(round.num_judged, 21u);
  EXPECT_DOUBLE_EQ(round.median_share, 0.70);
  // Absolute deviations: 0.00 (4 edges), 0.02 (8), 0.04 (8), 0.30 (1): median 0.02.
  EXPECT_NEAR(round.bound, 0.70 - 3.0 * 1.4826 * 0.02, 1e-12);
  ASSERT_EQ(round.removed.size(), 1u);
  EXPECT_EQ(round.removed[0], ViewPair(30, 31));
  EXPECT_EQ(round.edges.size(), 22u);
}

TEST(MissingCorrespondences, AWiderToleranceKeepsTheEdge) {
  MissingCorrespondenceOptions options;
  options.max_robust_deviations = 12.0;  // bound 0.70 - 0.356 = 0.344 < 0.40
  EXPECT_TRUE(JudgeObservedShares(ScatteredShares(), options).removed.empty());
}

TEST(MissingCorrespondences, TooFewJudgedEdgesGiveNoSpreadAndRemoveNothing) {
  std::vector<EdgeObservedShare> shares = ScatteredShares();
  shares.erase(shares.begin() + 5, shares.begin() + 20);  // five true-like edges and the low one left
  const MissingCorrespondenceRound round = JudgeObservedShares(shares, {});
  EXPECT_EQ(round.num_judged, 6u);
  EXPECT_TRUE(round.removed.empty());
}

TEST(MissingCorrespondences, OptionsCheckNamesTheSpoiledField) {
  using testing::CheckMessage;
  using testing::ExpectEachCaseNamesItsField;
  EXPECT_EQ(CheckMessage(MissingCorrespondenceOptions()), "");
  ExpectEachCaseNamesItsField<MissingCorrespondenceOptions>({
      {[](MissingCorrespondenceOptions* o) { o->max_rounds = 101; }, "MissingCorrespondenceOptions::max_rounds"},
      {[](MissingCorrespondenceOptions* o) { o->max_viewing_angle_deg = 0.0; },
       "MissingCorrespondenceOptions::max_viewing_angle_deg"},
      {[](MissingCorrespondenceOptions* o) { o->max_viewing_angle_deg = 120.0; },
       "MissingCorrespondenceOptions::max_viewing_angle_deg"},
      {[](MissingCorrespondenceOptions* o) { o->max_distance_ratio = 0.5; },
       "MissingCorrespondenceOptions::max_distance_ratio"},
      {[](MissingCorrespondenceOptions* o) { o->min_predicted_landmarks = 0; },
       "MissingCorrespondenceOptions::min_predicted_landmarks"},
      {[](MissingCorrespondenceOptions* o) { o->max_robust_deviations = testing::kNan; },
       "MissingCorrespondenceOptions::max_robust_deviations"},
  });
  // 0 rounds is "off", not out of range.
  EXPECT_EQ(CheckMessage<MissingCorrespondenceOptions>([](MissingCorrespondenceOptions* o) { o->max_rounds = 0; }),
            "");
}

}  // namespace
}  // namespace sfm_pruning
