// Every eval options struct's Check() (the evaluation, its alignment, the synthetic scenes): the
// defaults pass, and a value out of range fails with one line naming the field.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "sfm_pruning/eval/model_evaluation.hpp"
#include "sfm_pruning/eval/similarity_alignment.hpp"
#include "sfm_pruning/eval/synthetic_scene.hpp"
#include "sfm_pruning/util/error.hpp"
#include "support/option_checks.hpp"

namespace sfm_pruning {
namespace {

using testing::CheckMessage;
using testing::ExpectEachCaseNamesItsField;
using testing::kInf;
using testing::kNan;

TEST(EvalOptions, DefaultsPass) {
  EXPECT_NO_THROW(RobustSimilarityOptions().Check());
  EXPECT_NO_THROW(EvaluationOptions().Check());
  EXPECT_NO_THROW(SyntheticSceneOptions().Check());
}

TEST(EvalOptions, EvaluationAndAlignmentNameTheirBadField) {
  ExpectEachCaseNamesItsField<EvaluationOptions>({
      {[](EvaluationOptions* o) {
         o->auc_thresholds_deg = {3.0, 0.0, 10.0};
       },
       "EvaluationOptions::auc_thresholds_deg[1]"},
      {[](EvaluationOptions* o) { o->auc_thresholds_deg = {-5.0}; },
       "EvaluationOptions::auc_thresholds_deg[0]"},
      {[](EvaluationOptions* o) { o->auc_thresholds_deg = {kNan}; },
       "EvaluationOptions::auc_thresholds_deg[0]"},
      {[](EvaluationOptions* o) { o->auc_thresholds_deg = {kInf}; },
       "EvaluationOptions::auc_thresholds_deg[0]"},
      {[](EvaluationOptions* o) { o->alignment.inlier_threshold_scene_fraction = 0.0; },
       "RobustSimilarityOptions::inlier_threshold_scene_fraction"},
      {[](EvaluationOptions* o) { o->alignment.inlier_threshold_scene_fraction = -0.1; },
       "RobustSimilarityOptions::inlier_threshold_scene_fraction"},
      {[](EvaluationOptions* o) { o->alignment.inlier_threshold_scene_fraction = kNan; },
       "RobustSimilarityOptions::inlier_threshold_scene_fraction"},
      {[](EvaluationOptions* o) { o->alignment.max_iterations = 0; },
       "RobustSimilarityOptions::max_iterations"},
  });
  // No threshold: no AUC row, not an error.
  EvaluationOptions no_auc;
  no_auc.auc_thresholds_deg.clear();
  EXPECT_EQ(CheckMessage(no_auc), "");
}

TEST(EvalOptions, SyntheticSceneNamesItsBadField) {
  using O = SyntheticSceneOptions;
  ExpectEachCaseNamesItsField<O>({
      {[](O* o) { o->scene = "nowhere"; }, "SyntheticSceneOptions::scene"},
      {[](O* o) { o->num_views = 1; }, "SyntheticSceneOptions::num_views"},
      {[](O* o) { o->num_views = -36; }, "SyntheticSceneOptions::num_views"},
      {[](O* o) { o->image_width = 200000; }, "SyntheticSceneOptions::image_width"},
      {[](O* o) { o->image_height = 200000; }, "SyntheticSceneOptions::image_height"},
      {[](O* o) { o->focal_px = -1000.0; }, "SyntheticSceneOptions::focal_px"},
      {[](O* o) { o->focal_px = kNan; }, "SyntheticSceneOptions::focal_px"},
      {[](O* o) { o->focal_px = 1e308; }, "SyntheticSceneOptions::focal_px"},
      {[](O* o) { o->noise_px = -1.0; }, "SyntheticSceneOptions::noise_px"},
      {[](O* o) { o->noise_px = kInf; }, "SyntheticSceneOptions::noise_px"},
      {[](O* o) { o->descriptor_noise = 11.0; }, "SyntheticSceneOptions::descriptor_noise"},
      {[](O* o) { o->dropout = 1.0; }, "SyntheticSceneOptions::dropout"},
      {[](O* o) { o->dropout = kNan; }, "SyntheticSceneOptions::dropout"},
      {[](O* o) { o->clutter_ratio = kInf; }, "SyntheticSceneOptions::clutter_ratio"},
      {[](O* o) { o->max_incidence_deg = 0.0; }, "SyntheticSceneOptions::max_incidence_deg"},
      {[](O* o) { o->max_incidence_deg = 181.0; }, "SyntheticSceneOptions::max_incidence_deg"},
      {[](O* o) { o->max_distance_m = -40.0; }, "SyntheticSceneOptions::max_distance_m"},
      {[](O* o) { o->max_distance_m = kInf; }, "SyntheticSceneOptions::max_distance_m"},
      {[](O* o) { o->point_density_scale = 0.0; }, "SyntheticSceneOptions::point_density_scale"},
      {[](O* o) { o->point_density_scale = 1e308; }, "SyntheticSceneOptions::point_density_scale"},
      {[](O* o) { o->ratio_test = 1.5; }, "SyntheticSceneOptions::ratio_test"},
      {[](O* o) { o->outlier_ratio = 1.0; }, "SyntheticSceneOptions::outlier_ratio"},
      {[](O* o) { o->outlier_ratio = -0.2; }, "SyntheticSceneOptions::outlier_ratio"},
      {[](O* o) { o->min_matches = -1; }, "SyntheticSceneOptions::min_matches"},
      {[](O* o) { o->sequential_window = -5; }, "SyntheticSceneOptions::sequential_window"},
      {[](O* o) { o->loop_candidates = -3; }, "SyntheticSceneOptions::loop_candidates"},
      {[](O* o) { o->loop_min_gap = -50; }, "SyntheticSceneOptions::loop_min_gap"},
      {[](O* o) { o->laps = -2; }, "SyntheticSceneOptions::laps"},
      {[](O* o) { o->twin_fraction = 0.95; }, "SyntheticSceneOptions::twin_fraction"},
      {[](O* o) { o->twin_fraction = kNan; }, "SyntheticSceneOptions::twin_fraction"},
      {[](O* o) { o->loop_straight_per_radius = -3.0; }, "SyntheticSceneOptions::loop_straight_per_radius"},
      {[](O* o) { o->loop_straight_per_radius = 101.0; }, "SyntheticSceneOptions::loop_straight_per_radius"},
      {[](O* o) { o->street_module_width_m = 1.0; }, "SyntheticSceneOptions::street_module_width_m"},
      {[](O* o) { o->num_threads = -1; }, "SyntheticSceneOptions::num_threads"},
  });
}

TEST(EvalOptions, SyntheticSceneDefaultMarkersPass) {
  // 0 (twin_fraction: any negative value) takes the scene's default, on every scene.
  for (const std::string& name : SyntheticSceneNames()) {
    SyntheticSceneOptions options;
    options.scene = name;
    options.twin_fraction = -5.0;
    options.num_threads = 0;
    EXPECT_EQ(CheckMessage(options), "") << name;
  }
  // The ends of each range the CLI lets through.
  SyntheticSceneOptions ends;
  ends.num_views = 2;
  ends.image_width = kSyntheticLimits.max_image_side_px;
  ends.focal_px = 1e8;
  ends.noise_px = 0.0;
  ends.dropout = 0.99;
  ends.max_incidence_deg = 180.0;
  ends.max_distance_m = 1e6;
  ends.ratio_test = 1.0;
  ends.outlier_ratio = 0.0;
  ends.twin_fraction = 0.0;
  ends.loop_straight_per_radius = 100.0;
  ends.street_module_width_m = 2.0;
  EXPECT_EQ(CheckMessage(ends), "");
}

TEST(EvalOptions, EntryFunctionsRefuseBadOptionsBeforeAnyWork) {
  RobustSimilarityOptions alignment;
  alignment.max_iterations = -1;
  EXPECT_THROW(FitSimilarityRobust({}, {}, alignment), std::invalid_argument);

  EvaluationOptions evaluation;
  evaluation.auc_thresholds_deg = {0.0};
  // Not the Error of two models without a common image: the options are checked first.
  EXPECT_THROW(EvaluateModel(SfmData(), SfmData(), evaluation), std::invalid_argument);
  EXPECT_THROW(EvaluateMatchedCameras(CameraMatching(), evaluation), std::invalid_argument);

  // GenerateSyntheticScene keeps its documented Error, with the field's message.
  SyntheticSceneOptions scene;
  scene.dropout = 1.0;
  try {
    GenerateSyntheticScene(scene);
    ADD_FAILURE() << "no Error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("synthetic scene: SyntheticSceneOptions::dropout", 0), 0u)
        << e.what();
  }
}

}  // namespace
}  // namespace sfm_pruning
