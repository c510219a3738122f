// The GLOBAL pipeline started from a focal 30 % off (a camera without EXIF): view-graph focal
// calibration, verification with the calibrated focal, then the engine refining the focal in
// bundle adjustment. Scored with the evaluation module against the exact scene.
#include <gtest/gtest.h>

#include "calibration_test_scene.hpp"
#include "engine_test_scene.hpp"
#include "sfm_pruning/global/focal_calibration.hpp"

namespace sfm_pruning::calibration_test {
namespace {

using sfm_pruning::testing::AucAt;

struct PipelineRun {
  FocalCalibrationReport calibration;
  GlobalEngineReport engine;
  SfmData model;
};

PipelineRun RunWithWrongPrior(const Scene& scene, double focal_factor, bool calibrate, bool refine_in_bundle) {
  PipelineRun run;
  SfmData listing = ListingWithFocalOff(scene, focal_factor);
  if (calibrate) {
    const ViewGraph prior_graph = BuildViewGraphFromMatches({}, listing, scene.features, scene.matches);
    run.calibration = CalibrateFocalLengths({}, {0}, InliersOfEdges(prior_graph), scene.features, &listing);
  }
  const ViewGraph graph = BuildViewGraphFromMatches({}, listing, scene.features, scene.matches);
  GlobalEngineOptions options;
  options.bundle.refine_focal = refine_in_bundle;
  RunGlobalEngine(options, graph, listing, scene.features, &run.model, &run.engine);
  return run;
}

TEST(EngineCalibration, WrongFocalPriorStillGivesAccuratePoses) {
  const Scene scene = MakeScene({});
  const PipelineRun run = RunWithWrongPrior(scene, 1.3, true, true);
  ASSERT_TRUE(run.engine.success) << run.engine.message;
  ASSERT_EQ(run.calibration.intrinsics.size(), 1u);
  EXPECT_TRUE(run.calibration.intrinsics[0].accepted) << run.calibration.intrinsics[0].reason;
  EXPECT_EQ(run.engine.num_registered_views, scene.truth.views.size());
  // Bundle adjustment finishes what the calibration started.
  EXPECT_LT(std::abs(run.model.intrinsics.at(0).FocalLength() - 1000.0), 2.0);
  const EvaluationReport report = EvaluateModel(run.model, scene.truth);
  EXPECT_GE(AucAt(report, 3.0), 97.0);
}

TEST(EngineCalibration, WithoutCalibrationTheWrongPriorCostsAccuracy) {
  // The control: the same input with the prior held (what the engine did before) is clearly worse.
  const Scene scene = MakeScene({});
  const PipelineRun held = RunWithWrongPrior(scene, 1.3, false, false);
  const PipelineRun calibrated = RunWithWrongPrior(scene, 1.3, true, true);
  ASSERT_TRUE(calibrated.engine.success) << calibrated.engine.message;
  const double held_auc = held.engine.success ? AucAt(EvaluateModel(held.model, scene.truth), 3.0) : 0.0;
  EXPECT_LT(held_auc + 10.0, AucAt(EvaluateModel(calibrated.model, scene.truth), 3.0));
}

TEST(EngineCalibration, FocalSearchFindsAFocalFarFromTheGuess) {
  // The guess is half the true focal (COLMAP's 1.2 * width guess on templeSparseRing, where the
  // pairs' cost is flat and the calibration keeps it). The pairs are verified with the guess; the
  // focal search's quick solve finds the focal from there.
  const Scene scene = MakeScene({});
  SfmData listing = ListingWithFocalOff(scene, 0.5);
  const ViewGraph prior_graph = BuildViewGraphFromMatches({}, listing, scene.features, scene.matches);

  GlobalEngineOptions options;
  options.bundle.refine_focal = true;
  const GlobalEngineOptions search_options = WithFocalSearchSchedule(options);
  SfmData searched;
  GlobalEngineReport search;
  RunGlobalEngine(search_options, prior_graph, listing, scene.features, &searched, &search);
  ASSERT_TRUE(search.success) << search.message;
  ASSERT_EQ(search.bundle_adjustments.size(), 1u);  // one adjustment, no rounds
  EXPECT_LE(search.bundle_adjustments[0].num_iterations, 201);
  EXPECT_LE(search.bundle_adjustments[0].num_landmarks, 30u * scene.truth.views.size());  // the subset
  // Measured: 1000.2 px after 26 iterations (this scene has no focal-depth valley).
  EXPECT_LT(std::abs(searched.intrinsics.at(0).FocalLength() - 1000.0), 10.0);

  // The full solve from the searched focal, with the pairs verified again.
  listing.intrinsics.at(0).SetFocalLength(searched.intrinsics.at(0).FocalLength());
  const ViewGraph graph = BuildViewGraphFromMatches({}, listing, scene.features, scene.matches);
  SfmData model;
  GlobalEngineReport full;
  RunGlobalEngine(options, graph, listing, scene.features, &model, &full);
  ASSERT_TRUE(full.success) << full.message;
  EXPECT_LT(std::abs(model.intrinsics.at(0).FocalLength() - 1000.0), 2.0);
  EXPECT_GE(AucAt(EvaluateModel(model, scene.truth), 3.0), 97.0);
}

}  // namespace
}  // namespace sfm_pruning::calibration_test
