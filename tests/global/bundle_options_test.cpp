// Every options struct of the GLOBAL engine has a Check(): the defaults and the values the project
// sets pass, a value out of range fails with one line naming the field, and the entry functions
// refuse bad options before any work. Built into the bundle family's executable: every family
// links the whole module, and the engine family is labelled slow.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "sfm_pruning/global/focal_calibration.hpp"
#include "sfm_pruning/global/global_engine.hpp"
#include "sfm_pruning/global/rotation_irls.hpp"
#include "sfm_pruning/sfm/pose.hpp"
#include "support/option_checks.hpp"

namespace sfm_pruning {
namespace {

using testing::CheckMessage;
using testing::ExpectEachCaseNamesItsField;
using testing::kInf;
using testing::kNan;

TEST(GlobalOptions, DefaultsPass) {
  EXPECT_NO_THROW(RotationIncrementSolverOptions().Check());
  EXPECT_NO_THROW(RotationIrlsOptions().Check());
  EXPECT_NO_THROW(RotationAveragingOptions().Check());
  EXPECT_NO_THROW(TrackBuildingOptions().Check());
  EXPECT_NO_THROW(TrackSubsamplingOptions().Check());
  EXPECT_NO_THROW(PositioningSolverOptions().Check());
  EXPECT_NO_THROW(GlobalPositioningOptions().Check());
  EXPECT_NO_THROW(TranslationAveragingOptions().Check());
  EXPECT_NO_THROW(BundleAdjustmentOptions().Check());
  EXPECT_NO_THROW(StructureFilteringOptions().Check());
  EXPECT_NO_THROW(RetriangulationOptions().Check());
  EXPECT_NO_THROW(FocalCalibrationOptions().Check());
  EXPECT_NO_THROW(ViewGraphBuildOptions().Check());
  EXPECT_NO_THROW(GlobalEngineOptions().Check());
}

// The values the project and its tests set, and the documented "off" values, are in range.
TEST(GlobalOptions, ValuesInUseAndOffValuesPass) {
  EXPECT_EQ(CheckMessage<GlobalEngineOptions>([](GlobalEngineOptions* o) {
              *o = WithFocalSearchSchedule(*o);
              o->num_bundle_rounds = 0;
              o->intermediate_max_num_iterations = 1;
              o->positioning_random_starts = 3;
              o->positioning_start_screening_iterations = 25;
              o->bundle_adjust = false;
              o->tracks.min_track_length = 2;
              o->tracks.max_tracks_per_view = 1;
              o->tracks.max_num_tracks = 1;
              o->first_bundle_subsampling.max_tracks_per_view = 0;
              o->rotation.max_relative_rotation_error_deg = 0.5;
              o->rotation.max_l1_iterations = 0;
              o->bundle.huber_loss_scale_px = 0.0;           // plain least squares
              o->bundle.principal_point_prior_sigma = -1.0;  // off
              o->bundle.distortion_prior_sigma = 1e-5;
              o->global_positioning.solver.huber_scale = 0.0;
              o->global_positioning.solver.num_random_starts = 4;
              o->global_positioning.solver.start_screening_iterations = 5;
              o->global_positioning.subsampling = {60, 4};
              o->translation_averaging.solver.num_rejection_rounds = 0;
              o->filtering.min_triangulation_angle_deg = 0.0;
              o->retriangulation.min_triangulation_angle_deg = 0.0;
            }),
            "");
  EXPECT_EQ(CheckMessage<ViewGraphBuildOptions>([](ViewGraphBuildOptions* o) {
              o->num_threads = 0;  // <= 0: one worker
              o->keep_largest_component = false;
            }),
            "");
  EXPECT_EQ(CheckMessage<ViewGraphBuildOptions>([](ViewGraphBuildOptions* o) { o->num_threads = -2; }), "");
  for (const double nonzeros : {0.0, 1e9}) {  // always CG, always direct
    EXPECT_EQ(CheckMessage<RotationIncrementSolverOptions>([&](RotationIncrementSolverOptions* o) {
                o->max_direct_factor_nonzeros_per_view = nonzeros;
              }),
              "");
  }
  EXPECT_EQ(CheckMessage<RotationIrlsOptions>([](RotationIrlsOptions* o) {
              o->loss = RotationLoss::kL1;
              o->loss_scale_rad = DegToRad(0.05);  // the L1 stage's floor
              o->min_relative_cost_decrease = 1e-4;
              o->uniform_first_step = true;
            }),
            "");
}

TEST(GlobalOptions, RotationStructsNameTheirBadField) {
  ExpectEachCaseNamesItsField<RotationIncrementSolverOptions>({
      {[](RotationIncrementSolverOptions* o) { o->max_direct_factor_nonzeros_per_view = -1.0; },
       "RotationIncrementSolverOptions::max_direct_factor_nonzeros_per_view"},
      {[](RotationIncrementSolverOptions* o) { o->relative_tolerance = 0.0; },
       "RotationIncrementSolverOptions::relative_tolerance"},
      {[](RotationIncrementSolverOptions* o) { o->max_iterations = 0; },
       "RotationIncrementSolverOptions::max_iterations"},
  });
  ExpectEachCaseNamesItsField<RotationIrlsOptions>({
      {[](RotationIrlsOptions* o) { o->loss_scale_rad = 0.0; }, "RotationIrlsOptions::loss_scale_rad"},
      {[](RotationIrlsOptions* o) { o->max_iterations = -1; }, "RotationIrlsOptions::max_iterations"},
      {[](RotationIrlsOptions* o) { o->convergence_tolerance_rad = -1e-8; },
       "RotationIrlsOptions::convergence_tolerance_rad"},
      {[](RotationIrlsOptions* o) { o->min_relative_cost_decrease = kNan; },
       "RotationIrlsOptions::min_relative_cost_decrease"},
      {[](RotationIrlsOptions* o) { o->linear_solver.relative_tolerance = 2.0; },
       "RotationIncrementSolverOptions::relative_tolerance"},
  });
  ExpectEachCaseNamesItsField<RotationAveragingOptions>({
      {[](RotationAveragingOptions* o) { o->max_relative_rotation_error_deg = 0.0; },
       "RotationAveragingOptions::max_relative_rotation_error_deg"},
      {[](RotationAveragingOptions* o) { o->max_relative_rotation_error_deg = kNan; },
       "RotationAveragingOptions::max_relative_rotation_error_deg"},
      {[](RotationAveragingOptions* o) { o->max_l1_iterations = -1; },
       "RotationAveragingOptions::max_l1_iterations"},
      {[](RotationAveragingOptions* o) { o->l1_residual_floor_deg = 0.0; },
       "RotationAveragingOptions::l1_residual_floor_deg"},
      {[](RotationAveragingOptions* o) { o->l1_convergence_tolerance_rad = -1.0; },
       "RotationAveragingOptions::l1_convergence_tolerance_rad"},
      {[](RotationAveragingOptions* o) { o->l1_min_relative_cost_decrease = 1.5; },
       "RotationAveragingOptions::l1_min_relative_cost_decrease"},
      {[](RotationAveragingOptions* o) { o->max_irls_iterations = -1; },
       "RotationAveragingOptions::max_irls_iterations"},
      {[](RotationAveragingOptions* o) { o->irls_loss_scale_deg = -5.0; },
       "RotationAveragingOptions::irls_loss_scale_deg"},
      {[](RotationAveragingOptions* o) { o->convergence_tolerance_rad = kNan; },
       "RotationAveragingOptions::convergence_tolerance_rad"},
      {[](RotationAveragingOptions* o) { o->linear_solver_relative_tolerance = 0.0; },
       "RotationAveragingOptions::linear_solver_relative_tolerance"},
      {[](RotationAveragingOptions* o) { o->max_linear_solver_iterations = 0; },
       "RotationAveragingOptions::max_linear_solver_iterations"},
  });
}

TEST(GlobalOptions, TrackStructsNameTheirBadField) {
  ExpectEachCaseNamesItsField<TrackBuildingOptions>({
      {[](TrackBuildingOptions* o) { o->min_track_length = 1; }, "TrackBuildingOptions::min_track_length"},
  });
  ExpectEachCaseNamesItsField<TrackSubsamplingOptions>({
      {[](TrackSubsamplingOptions* o) { o->grid_cells = 0; }, "TrackSubsamplingOptions::grid_cells"},
  });
}

TEST(GlobalOptions, PositioningStructsNameTheirBadField) {
  ExpectEachCaseNamesItsField<PositioningSolverOptions>({
      {[](PositioningSolverOptions* o) { o->huber_scale = kNan; }, "PositioningSolverOptions::huber_scale"},
      {[](PositioningSolverOptions* o) { o->min_ray_scale = 0.0; },
       "PositioningSolverOptions::min_ray_scale"},
      {[](PositioningSolverOptions* o) { o->init_cube_half_size = 0.0; },
       "PositioningSolverOptions::init_cube_half_size"},
      {[](PositioningSolverOptions* o) { o->num_random_starts = 0; },
       "PositioningSolverOptions::num_random_starts"},
      {[](PositioningSolverOptions* o) { o->start_screening_iterations = -1; },
       "PositioningSolverOptions::start_screening_iterations"},
      {[](PositioningSolverOptions* o) { o->num_rejection_rounds = -1; },
       "PositioningSolverOptions::num_rejection_rounds"},
      {[](PositioningSolverOptions* o) { o->rejection_threshold_deg = 0.0; },
       "PositioningSolverOptions::rejection_threshold_deg"},
      {[](PositioningSolverOptions* o) { o->max_num_iterations = -1; },
       "PositioningSolverOptions::max_num_iterations"},
      {[](PositioningSolverOptions* o) { o->max_num_resolve_iterations = -1; },
       "PositioningSolverOptions::max_num_resolve_iterations"},
      {[](PositioningSolverOptions* o) { o->function_tolerance = -1.0; },
       "PositioningSolverOptions::function_tolerance"},
      {[](PositioningSolverOptions* o) { o->gradient_tolerance = kNan; },
       "PositioningSolverOptions::gradient_tolerance"},
      {[](PositioningSolverOptions* o) { o->parameter_tolerance = -1.0; },
       "PositioningSolverOptions::parameter_tolerance"},
      {[](PositioningSolverOptions* o) { o->num_threads = 0; }, "PositioningSolverOptions::num_threads"},
  });
  ExpectEachCaseNamesItsField<GlobalPositioningOptions>({
      {[](GlobalPositioningOptions* o) { o->solver.min_ray_scale = -1e-3; },
       "PositioningSolverOptions::min_ray_scale"},
      {[](GlobalPositioningOptions* o) { o->max_angular_residual_deg = 0.0; },
       "GlobalPositioningOptions::max_angular_residual_deg"},
      {[](GlobalPositioningOptions* o) { o->subsampling.grid_cells = 0; },
       "TrackSubsamplingOptions::grid_cells"},
  });
  ExpectEachCaseNamesItsField<TranslationAveragingOptions>({
      {[](TranslationAveragingOptions* o) { o->solver.num_threads = 0; },
       "PositioningSolverOptions::num_threads"},
      {[](TranslationAveragingOptions* o) { o->max_angular_residual_deg = 200.0; },
       "TranslationAveragingOptions::max_angular_residual_deg"},
  });
}

TEST(GlobalOptions, BundleStructsNameTheirBadField) {
  ExpectEachCaseNamesItsField<BundleAdjustmentOptions>({
      {[](BundleAdjustmentOptions* o) { o->huber_loss_scale_px = kNan; },
       "BundleAdjustmentOptions::huber_loss_scale_px"},
      {[](BundleAdjustmentOptions* o) { o->principal_point_prior_sigma = kNan; },
       "BundleAdjustmentOptions::principal_point_prior_sigma"},
      {[](BundleAdjustmentOptions* o) { o->distortion_prior_sigma = kNan; },
       "BundleAdjustmentOptions::distortion_prior_sigma"},
      {[](BundleAdjustmentOptions* o) { o->max_num_iterations = -1; },
       "BundleAdjustmentOptions::max_num_iterations"},
      {[](BundleAdjustmentOptions* o) { o->function_tolerance = -1e-6; },
       "BundleAdjustmentOptions::function_tolerance"},
      {[](BundleAdjustmentOptions* o) { o->gradient_tolerance = kNan; },
       "BundleAdjustmentOptions::gradient_tolerance"},
      {[](BundleAdjustmentOptions* o) { o->parameter_tolerance = -1.0; },
       "BundleAdjustmentOptions::parameter_tolerance"},
      {[](BundleAdjustmentOptions* o) { o->num_threads = 0; }, "BundleAdjustmentOptions::num_threads"},
      {[](BundleAdjustmentOptions* o) { o->min_observations_per_thread = 0; },
       "BundleAdjustmentOptions::min_observations_per_thread"},
  });
  ExpectEachCaseNamesItsField<StructureFilteringOptions>({
      {[](StructureFilteringOptions* o) { o->max_reprojection_error_px = 0.0; },
       "StructureFilteringOptions::max_reprojection_error_px"},
      {[](StructureFilteringOptions* o) { o->min_triangulation_angle_deg = -1.0; },
       "StructureFilteringOptions::min_triangulation_angle_deg"},
      {[](StructureFilteringOptions* o) { o->min_num_observations = 1; },
       "StructureFilteringOptions::min_num_observations"},
  });
  ExpectEachCaseNamesItsField<RetriangulationOptions>({
      {[](RetriangulationOptions* o) { o->max_reprojection_error_px = kNan; },
       "RetriangulationOptions::max_reprojection_error_px"},
      {[](RetriangulationOptions* o) { o->min_triangulation_angle_deg = 181.0; },
       "RetriangulationOptions::min_triangulation_angle_deg"},
  });
}

TEST(GlobalOptions, CalibrationAndVerificationStructsNameTheirBadField) {
  ExpectEachCaseNamesItsField<FocalCalibrationOptions>({
      {[](FocalCalibrationOptions* o) { o->min_focal_ratio = 0.0; },
       "FocalCalibrationOptions::min_focal_ratio"},
      {[](FocalCalibrationOptions* o) { o->max_focal_ratio = kInf; },
       "FocalCalibrationOptions::max_focal_ratio"},
      {[](FocalCalibrationOptions* o) { o->max_focal_ratio = 0.1; },
       "FocalCalibrationOptions::max_focal_ratio"},
      {[](FocalCalibrationOptions* o) { o->num_grid_steps = 1; }, "FocalCalibrationOptions::num_grid_steps"},
      {[](FocalCalibrationOptions* o) { o->gap_loss_scale = 0.0; },
       "FocalCalibrationOptions::gap_loss_scale"},
      {[](FocalCalibrationOptions* o) { o->min_f_definition = -1.0; },
       "FocalCalibrationOptions::min_f_definition"},
      {[](FocalCalibrationOptions* o) { o->sampson_scale_px = 0.0; },
       "FocalCalibrationOptions::sampson_scale_px"},
      {[](FocalCalibrationOptions* o) { o->min_pairs_per_intrinsic = 0; },
       "FocalCalibrationOptions::min_pairs_per_intrinsic"},
      {[](FocalCalibrationOptions* o) { o->sharpness_step = 0.0; },
       "FocalCalibrationOptions::sharpness_step"},
      {[](FocalCalibrationOptions* o) { o->min_sharpness = kNan; }, "FocalCalibrationOptions::min_sharpness"},
  });
  // The pair verification's own options (geometry/two_view_geometry.hpp) name themselves.
  ExpectEachCaseNamesItsField<ViewGraphBuildOptions>({
      {[](ViewGraphBuildOptions* o) { o->two_view.min_inlier_ratio = 1.5; },
       "TwoViewGeometryOptions::min_inlier_ratio"},
  });
}

TEST(GlobalOptions, EngineOptionsCheckEveryNestedStruct) {
  ExpectEachCaseNamesItsField<GlobalEngineOptions>({
      {[](GlobalEngineOptions* o) { o->rotation.max_relative_rotation_error_deg = 0.0; },
       "RotationAveragingOptions::max_relative_rotation_error_deg"},
      {[](GlobalEngineOptions* o) { o->tracks.min_track_length = 0; },
       "TrackBuildingOptions::min_track_length"},
      {[](GlobalEngineOptions* o) { o->global_positioning.max_angular_residual_deg = -3.0; },
       "GlobalPositioningOptions::max_angular_residual_deg"},
      {[](GlobalEngineOptions* o) { o->global_positioning.solver.init_cube_half_size = kNan; },
       "PositioningSolverOptions::init_cube_half_size"},
      {[](GlobalEngineOptions* o) { o->translation_averaging.solver.huber_scale = kNan; },
       "PositioningSolverOptions::huber_scale"},
      {[](GlobalEngineOptions* o) { o->translation_averaging.max_angular_residual_deg = 0.0; },
       "TranslationAveragingOptions::max_angular_residual_deg"},
      {[](GlobalEngineOptions* o) { o->bundle.num_threads = 0; }, "BundleAdjustmentOptions::num_threads"},
      {[](GlobalEngineOptions* o) { o->filtering.min_num_observations = 0; },
       "StructureFilteringOptions::min_num_observations"},
      {[](GlobalEngineOptions* o) { o->retriangulation.max_reprojection_error_px = 0.0; },
       "RetriangulationOptions::max_reprojection_error_px"},
      {[](GlobalEngineOptions* o) { o->num_bundle_rounds = -1; }, "GlobalEngineOptions::num_bundle_rounds"},
      {[](GlobalEngineOptions* o) { o->first_bundle_subsampling.grid_cells = 0; },
       "TrackSubsamplingOptions::grid_cells"},
      {[](GlobalEngineOptions* o) { o->positioning_function_tolerance = -1.0; },
       "GlobalEngineOptions::positioning_function_tolerance"},
      {[](GlobalEngineOptions* o) { o->positioning_max_num_iterations = -1; },
       "GlobalEngineOptions::positioning_max_num_iterations"},
      {[](GlobalEngineOptions* o) { o->positioning_max_num_resolve_iterations = -1; },
       "GlobalEngineOptions::positioning_max_num_resolve_iterations"},
      {[](GlobalEngineOptions* o) { o->positioning_random_starts = 0; },
       "GlobalEngineOptions::positioning_random_starts"},
      {[](GlobalEngineOptions* o) { o->positioning_start_screening_iterations = -1; },
       "GlobalEngineOptions::positioning_start_screening_iterations"},
      {[](GlobalEngineOptions* o) { o->intermediate_function_tolerance = kNan; },
       "GlobalEngineOptions::intermediate_function_tolerance"},
      {[](GlobalEngineOptions* o) { o->final_function_tolerance = -1e-5; },
       "GlobalEngineOptions::final_function_tolerance"},
      {[](GlobalEngineOptions* o) { o->intermediate_max_num_iterations = -1; },
       "GlobalEngineOptions::intermediate_max_num_iterations"},
      {[](GlobalEngineOptions* o) { o->num_threads = 0; }, "GlobalEngineOptions::num_threads"},
  });
}

// The entry functions check their options first: on empty inputs, which good options turn into a
// failed report or an empty result, bad ones throw.
TEST(GlobalOptions, EntryFunctionsRefuseBadOptionsBeforeAnyWork) {
  GlobalEngineOptions engine;
  engine.num_threads = 0;
  SfmData out;
  GlobalEngineReport report;
  EXPECT_THROW(RunGlobalEngine(engine, ViewGraph(), SfmData(), FeaturesPerView(), &out, &report),
               std::invalid_argument);
  EXPECT_THROW(RefineGlobalModel(engine, ViewGraph(), SfmData(), FeaturesPerView(), &out, &report),
               std::invalid_argument);
  RunGlobalEngine(GlobalEngineOptions(), ViewGraph(), SfmData(), FeaturesPerView(), &out, &report);
  EXPECT_FALSE(report.success);

  ViewGraphBuildOptions build;
  build.two_view.min_inlier_ratio = -0.25;
  EXPECT_THROW(BuildViewGraphFromMatches(build, SfmData(), FeaturesPerView(), PairwiseMatches()),
               std::invalid_argument);
  EXPECT_THROW(BuildViewGraphFromVerifiedPairs(build, SfmData(), FeaturesPerView(), VerifiedPairs()),
               std::invalid_argument);
  EXPECT_EQ(
      BuildViewGraphFromMatches(ViewGraphBuildOptions(), SfmData(), FeaturesPerView(), PairwiseMatches())
          .NumNodes(),
      0u);

  FocalCalibrationOptions calibration;
  calibration.min_focal_ratio = 10.0;  // above max_focal_ratio
  SfmData scene;
  EXPECT_THROW(CalibrateFocalLengths(calibration, {}, PairInliers(), FeaturesPerView(), &scene),
               std::invalid_argument);
  EXPECT_TRUE(CalibrateFocalLengths({}, {}, PairInliers(), FeaturesPerView(), &scene).intrinsics.empty());

  RotationIrlsOptions irls;
  irls.loss_scale_rad = kNan;
  std::vector<Eigen::Matrix3d> rotations;
  EXPECT_THROW(RefineRotationsIrls(RotationProblem(), 0, irls, &rotations), std::invalid_argument);
}

}  // namespace
}  // namespace sfm_pruning
