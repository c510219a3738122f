// Every front-end options struct's Check(): the defaults pass, and a value out of range fails with
// one line naming the field.
#include <gtest/gtest.h>

#include <stdexcept>

#include "sfm_pruning/features/descriptor_matching.hpp"
#include "sfm_pruning/features/focal_prior.hpp"
#include "sfm_pruning/features/image_listing.hpp"
#include "sfm_pruning/features/sift_extraction.hpp"
#include "support/option_checks.hpp"

namespace sfm_pruning {
namespace {

using testing::CheckMessage;
using testing::ExpectEachCaseNamesItsField;
using testing::kInf;
using testing::kNan;

TEST(FeaturesOptions, DefaultsPass) {
  EXPECT_NO_THROW(FocalPriorOptions().Check());
  EXPECT_NO_THROW(ImageListingOptions().Check());
  EXPECT_NO_THROW(SiftOptions().Check());
  EXPECT_NO_THROW(DescriptorMatchingOptions().Check());
}

TEST(FeaturesOptions, ImageListingNamesItsBadField) {
  ExpectEachCaseNamesItsField<ImageListingOptions>({
      {[](ImageListingOptions* o) { o->focal_px = 0.0; }, "ImageListingOptions::focal_px"},
      {[](ImageListingOptions* o) { o->focal_px = -500.0; }, "ImageListingOptions::focal_px"},
      {[](ImageListingOptions* o) { o->focal_px = kInf; }, "ImageListingOptions::focal_px"},
      {[](ImageListingOptions* o) { o->K = Eigen::Matrix3d::Zero(); }, "ImageListingOptions::K"},
      {[](ImageListingOptions* o) {
         Eigen::Matrix3d K = Eigen::Matrix3d::Identity();
         K(0, 2) = kNan;
         o->K = K;
       },
       "ImageListingOptions::K"},
      {[](ImageListingOptions* o) { o->num_threads = 0; }, "ImageListingOptions::num_threads"},
      {[](ImageListingOptions* o) { o->focal.sensor_width_mm = -7.2; }, "FocalPriorOptions::sensor_width_mm"},
      {[](ImageListingOptions* o) { o->focal.sensor_width_mm = kNan; }, "FocalPriorOptions::sensor_width_mm"},
      {[](ImageListingOptions* o) { o->focal.default_focal_factor = 0.0; },
       "FocalPriorOptions::default_focal_factor"},
      {[](ImageListingOptions* o) { o->focal.default_focal_factor = 2000.0; },
       "FocalPriorOptions::default_focal_factor"},
  });
  // What the CLI sets: a focal, a K file's matrix, a sensor width.
  ImageListingOptions given;
  given.focal_px = 100.0;
  Eigen::Matrix3d K;
  K << 2759.48, 0, 1520.69, 0, 2764.16, 1006.81, 0, 0, 1;
  given.K = K;
  given.focal.sensor_width_mm = 7.2;
  given.num_threads = 4;
  EXPECT_EQ(CheckMessage(given), "");
}

TEST(FeaturesOptions, SiftNamesItsBadField) {
  ExpectEachCaseNamesItsField<SiftOptions>({
      {[](SiftOptions* o) { o->max_features = -1; }, "SiftOptions::max_features"},
      {[](SiftOptions* o) { o->max_image_size = -1600; }, "SiftOptions::max_image_size"},
      {[](SiftOptions* o) { o->contrast_threshold = -0.02; }, "SiftOptions::contrast_threshold"},
      {[](SiftOptions* o) { o->contrast_threshold = kNan; }, "SiftOptions::contrast_threshold"},
      {[](SiftOptions* o) { o->edge_threshold = 0.0; }, "SiftOptions::edge_threshold"},
      {[](SiftOptions* o) { o->edge_threshold = kInf; }, "SiftOptions::edge_threshold"},
      {[](SiftOptions* o) { o->num_octave_layers = 0; }, "SiftOptions::num_octave_layers"},
      {[](SiftOptions* o) { o->num_threads = 0; }, "SiftOptions::num_threads"},
  });
  // 0: no cap on the count, no downscaling.
  SiftOptions unlimited;
  unlimited.max_features = 0;
  unlimited.max_image_size = 0;
  unlimited.contrast_threshold = 0.0;
  EXPECT_EQ(CheckMessage(unlimited), "");
}

TEST(FeaturesOptions, DescriptorMatchingNamesItsBadField) {
  ExpectEachCaseNamesItsField<DescriptorMatchingOptions>({
      {[](DescriptorMatchingOptions* o) { o->max_ratio = 0.0; }, "DescriptorMatchingOptions::max_ratio"},
      {[](DescriptorMatchingOptions* o) { o->max_ratio = 1.2; }, "DescriptorMatchingOptions::max_ratio"},
      {[](DescriptorMatchingOptions* o) { o->max_ratio = kNan; }, "DescriptorMatchingOptions::max_ratio"},
      {[](DescriptorMatchingOptions* o) { o->flann_trees = 0; }, "DescriptorMatchingOptions::flann_trees"},
      {[](DescriptorMatchingOptions* o) { o->flann_checks = 0; }, "DescriptorMatchingOptions::flann_checks"},
      {[](DescriptorMatchingOptions* o) { o->min_num_matches = -1; },
       "DescriptorMatchingOptions::min_num_matches"},
      {[](DescriptorMatchingOptions* o) { o->num_threads = -2; }, "DescriptorMatchingOptions::num_threads"},
  });
  // What the tests and the CLI use: no ratio test (1), every pair with a match (0 or 1).
  DescriptorMatchingOptions loose;
  loose.max_ratio = 1.0;
  loose.min_num_matches = 0;
  EXPECT_EQ(CheckMessage(loose), "");
}

TEST(FeaturesOptions, EntryFunctionsRefuseBadOptionsBeforeAnyWork) {
  ImageListingOptions listing;
  listing.num_threads = 0;
  // Not the Error of a missing folder: the options are checked first.
  EXPECT_THROW(ListImages("/nonexistent/prunesfm/images", listing), std::invalid_argument);

  FocalPriorOptions focal;
  focal.default_focal_factor = -1.0;
  EXPECT_THROW(FocalFromExif(nullptr, 640, 480, focal), std::invalid_argument);

  SiftOptions sift;
  sift.num_octave_layers = 0;
  EXPECT_THROW(ExtractFeatures(SfmData(), sift, nullptr), std::invalid_argument);
  EXPECT_THROW(ExtractSift(cv::Mat(), sift), std::invalid_argument);

  DescriptorMatchingOptions matching;
  matching.max_ratio = 2.0;
  EXPECT_THROW(MatchDescriptors(FeaturesPerView(), PairSet(), matching), std::invalid_argument);
}

}  // namespace
}  // namespace sfm_pruning
