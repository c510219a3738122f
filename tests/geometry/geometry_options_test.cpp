// Every geometry options struct's Check(): the defaults pass, and a value out of range fails with
// one line naming the field.
#include <gtest/gtest.h>

#include <stdexcept>

#include "sfm_pruning/geometry/fundamental_matrix.hpp"
#include "sfm_pruning/geometry/opengv_absolute_pose.hpp"
#include "sfm_pruning/geometry/opengv_relative_pose.hpp"
#include "sfm_pruning/geometry/ransac_options.hpp"
#include "sfm_pruning/geometry/relative_pose_refinement.hpp"
#include "sfm_pruning/geometry/so3.hpp"
#include "sfm_pruning/geometry/two_view_geometry.hpp"
#include "support/option_checks.hpp"

namespace sfm_pruning {
namespace {

using testing::CheckMessage;
using testing::ExpectEachCaseNamesItsField;
using testing::kInf;
using testing::kNan;

TEST(GeometryOptions, DefaultsPass) {
  EXPECT_NO_THROW(GeodesicMeanOptions().Check());
  EXPECT_NO_THROW(RansacOptions().Check());
  EXPECT_NO_THROW(FundamentalMatrixOptions().Check());
  EXPECT_NO_THROW(AbsolutePoseOptions().Check());
  EXPECT_NO_THROW(RelativePoseRefinementOptions().Check());
  EXPECT_NO_THROW(RelativePoseOptions().Check());
  EXPECT_NO_THROW(TwoViewGeometryOptions().Check());
}

TEST(GeometryOptions, GeodesicMeanNamesItsBadField) {
  using O = GeodesicMeanOptions;
  ExpectEachCaseNamesItsField<O>({
      {[](O* o) { o->max_iterations = -1; }, "GeodesicMeanOptions::max_iterations"},
      {[](O* o) { o->convergence_tolerance_rad = kNan; }, "GeodesicMeanOptions::convergence_tolerance_rad"},
      {[](O* o) { o->convergence_tolerance_rad = -1e-9; }, "GeodesicMeanOptions::convergence_tolerance_rad"},
      {[](O* o) { o->l1_min_residual_rad = 0.0; }, "GeodesicMeanOptions::l1_min_residual_rad"},
      {[](O* o) { o->l1_min_residual_rad = 4.0; }, "GeodesicMeanOptions::l1_min_residual_rad"},
  });
  // 0 iterations (the chordal mean) and a tolerance of 0 (every iteration) are legal.
  EXPECT_EQ(CheckMessage<O>([](O* o) {
              o->max_iterations = 0;
              o->convergence_tolerance_rad = 0.0;
            }),
            "");
}

TEST(GeometryOptions, RansacNamesItsBadField) {
  using O = RansacOptions;
  ExpectEachCaseNamesItsField<O>({
      {[](O* o) { o->max_iterations = 0; }, "RansacOptions::max_iterations"},
      {[](O* o) { o->confidence = 1.5; }, "RansacOptions::confidence"},
      {[](O* o) { o->confidence = -0.1; }, "RansacOptions::confidence"},
      {[](O* o) { o->confidence = kNan; }, "RansacOptions::confidence"},
  });
  EXPECT_EQ(CheckMessage<O>([](O* o) { o->confidence = 1.0; }), "");
}

TEST(GeometryOptions, FundamentalMatrixNamesItsBadField) {
  using O = FundamentalMatrixOptions;
  ExpectEachCaseNamesItsField<O>({
      {[](O* o) { o->robust_scale = 0.0; }, "FundamentalMatrixOptions::robust_scale"},
      {[](O* o) { o->robust_scale = kNan; }, "FundamentalMatrixOptions::robust_scale"},
      {[](O* o) { o->num_reweighting_iterations = -1; }, "FundamentalMatrixOptions::num_reweighting_iterations"},
  });
  // An infinite scale is the plain Sampson fit; 0 passes are the linear fit only.
  EXPECT_EQ(CheckMessage<O>([](O* o) {
              o->robust_scale = kInf;
              o->num_reweighting_iterations = 0;
            }),
            "");
}

TEST(GeometryOptions, AbsolutePoseNamesItsBadField) {
  using O = AbsolutePoseOptions;
  ExpectEachCaseNamesItsField<O>({
      {[](O* o) { o->max_angular_error_deg = 0.0; }, "AbsolutePoseOptions::max_angular_error_deg"},
      {[](O* o) { o->max_angular_error_deg = kNan; }, "AbsolutePoseOptions::max_angular_error_deg"},
      {[](O* o) { o->max_reprojection_error_px = -4.0; }, "AbsolutePoseOptions::max_reprojection_error_px"},
      {[](O* o) { o->focal_length_px = kNan; }, "AbsolutePoseOptions::focal_length_px"},
      {[](O* o) { o->ransac.max_iterations = -5; }, "RansacOptions::max_iterations"},
      {[](O* o) { o->refinement_rounds = -1; }, "AbsolutePoseOptions::refinement_rounds"},
      {[](O* o) { o->min_num_inliers = -1; }, "AbsolutePoseOptions::min_num_inliers"},
  });
  // The pixel threshold with its focal length still unknown (subgraph_edge_placement fills it in).
  EXPECT_EQ(CheckMessage<O>([](O* o) {
              o->max_reprojection_error_px = 4.0;
              o->focal_length_px = 0.0;
              o->refinement_rounds = 0;
            }),
            "");
}

TEST(GeometryOptions, RelativePoseRefinementNamesItsBadField) {
  using O = RelativePoseRefinementOptions;
  ExpectEachCaseNamesItsField<O>({
      {[](O* o) { o->loss_scale_rad = kNan; }, "RelativePoseRefinementOptions::loss_scale_rad"},
      {[](O* o) { o->loss_scale_rad = kInf; }, "RelativePoseRefinementOptions::loss_scale_rad"},
      {[](O* o) { o->max_num_iterations = -1; }, "RelativePoseRefinementOptions::max_num_iterations"},
  });
  // <= 0 is documented as plain least squares.
  EXPECT_EQ(CheckMessage<O>([](O* o) { o->loss_scale_rad = -1.0; }), "");
  EXPECT_EQ(CheckMessage<O>([](O* o) { o->loss_scale_rad = 0.01; }), "");
}

TEST(GeometryOptions, RelativePoseNamesItsBadField) {
  using O = RelativePoseOptions;
  ExpectEachCaseNamesItsField<O>({
      {[](O* o) { o->max_angular_error_deg = 0.0; }, "RelativePoseOptions::max_angular_error_deg"},
      {[](O* o) { o->max_angular_error_deg = 91.0; }, "RelativePoseOptions::max_angular_error_deg"},
      {[](O* o) { o->max_angular_error_deg = kNan; }, "RelativePoseOptions::max_angular_error_deg"},
      {[](O* o) { o->ransac.confidence = 2.0; }, "RansacOptions::confidence"},
      {[](O* o) { o->refinement_rounds = -1; }, "RelativePoseOptions::refinement_rounds"},
      {[](O* o) { o->precision_check_ratio = -0.5; }, "RelativePoseOptions::precision_check_ratio"},
      {[](O* o) { o->precision_check_ratio = 1.5; }, "RelativePoseOptions::precision_check_ratio"},
  });
  // What the CLI allows (--max_epipolar_error_deg up to 90, --verification_precision_ratio 0 = off).
  EXPECT_EQ(CheckMessage<O>([](O* o) {
              o->max_angular_error_deg = 90.0;
              o->precision_check_ratio = 0.0;
              o->refinement_rounds = 0;
            }),
            "");
  EXPECT_EQ(CheckMessage<O>([](O* o) { o->precision_check_ratio = 0.99; }), "");
}

TEST(GeometryOptions, TwoViewGeometryNamesItsBadField) {
  using O = TwoViewGeometryOptions;
  ExpectEachCaseNamesItsField<O>({
      {[](O* o) { o->min_num_inliers = -1; }, "TwoViewGeometryOptions::min_num_inliers"},
      {[](O* o) { o->min_inlier_ratio = 1.25; }, "TwoViewGeometryOptions::min_inlier_ratio"},
      {[](O* o) { o->min_inlier_ratio = kNan; }, "TwoViewGeometryOptions::min_inlier_ratio"},
      {[](O* o) { o->relative_pose.max_angular_error_deg = -0.25; }, "RelativePoseOptions::max_angular_error_deg"},
      {[](O* o) { o->relative_pose.ransac.max_iterations = 0; }, "RansacOptions::max_iterations"},
  });
  EXPECT_EQ(CheckMessage<O>([](O* o) {
              o->min_num_inliers = 0;
              o->min_inlier_ratio = 0.0;
            }),
            "");
}

// The entry functions refuse bad options before any work, also on inputs they would skip.
TEST(GeometryOptions, EntryFunctionsRefuseBadOptions) {
  GeodesicMeanOptions mean;
  mean.l1_min_residual_rad = -1.0;
  EXPECT_THROW(GeodesicMeanRotation({}, mean), std::invalid_argument);

  FundamentalMatrixOptions fundamental;
  fundamental.robust_scale = 0.0;
  Eigen::Matrix3d F;
  EXPECT_THROW(EstimateFundamentalMatrix({}, {}, fundamental, &F), std::invalid_argument);

  AbsolutePoseOptions absolute;
  absolute.ransac.confidence = kNan;
  EXPECT_THROW(EstimateAbsolutePose({}, {}, absolute), std::invalid_argument);

  RelativePoseRefinementOptions refinement;
  refinement.max_num_iterations = -1;
  RelativePose pose;
  EXPECT_THROW(RefineRelativePose({}, {}, {}, refinement, &pose), std::invalid_argument);

  RelativePoseOptions relative;
  relative.precision_check_ratio = 2.0;
  EXPECT_THROW(EstimateRelativePose({}, {}, relative), std::invalid_argument);

  TwoViewGeometryOptions two_view;
  two_view.min_inlier_ratio = -0.1;
  EXPECT_THROW(EstimateTwoViewGeometry(FeatureSet(), CameraIntrinsics(), FeatureSet(), CameraIntrinsics(), {}, two_view),
               std::invalid_argument);
}

}  // namespace
}  // namespace sfm_pruning
