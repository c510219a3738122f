// Every export options struct's Check(): the defaults pass, and a value out of range fails with
// one line naming the field.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <stdexcept>

#include "sfm_pruning/export/dense_workspaces.hpp"
#include "sfm_pruning/export/undistorted_model.hpp"
#include "sfm_pruning/export/undistortion.hpp"
#include "support/option_checks.hpp"

namespace sfm_pruning {
namespace {
namespace fs = std::filesystem;

using testing::CheckMessage;
using testing::ExpectEachCaseNamesItsField;
using testing::kInf;
using testing::kNan;

TEST(ExportOptions, DefaultsPass) {
  EXPECT_NO_THROW(UndistortOptions().Check());
  EXPECT_NO_THROW(ImageWriteOptions().Check());
  EXPECT_NO_THROW(DenseWorkspaceOptions().Check());
}

// Every struct is reached through DenseWorkspaceOptions, which checks the ones it holds.
TEST(ExportOptions, EachStructNamesItsBadField) {
  ExpectEachCaseNamesItsField<DenseWorkspaceOptions>({
      {[](DenseWorkspaceOptions* o) { o->undistort.min_focal_scale = -0.2; },
       "UndistortOptions::min_focal_scale"},
      {[](DenseWorkspaceOptions* o) { o->undistort.min_focal_scale = kNan; },
       "UndistortOptions::min_focal_scale"},
      {[](DenseWorkspaceOptions* o) { o->undistort.min_focal_scale = kInf; },
       "UndistortOptions::min_focal_scale"},
      {[](DenseWorkspaceOptions* o) { o->undistort.max_focal_scale = 0.0; },
       "UndistortOptions::max_focal_scale"},
      {[](DenseWorkspaceOptions* o) { o->undistort.max_focal_scale = 0.1; },
       "UndistortOptions::max_focal_scale"},
      {[](DenseWorkspaceOptions* o) { o->undistort.max_focal_scale = kNan; },
       "UndistortOptions::max_focal_scale"},
      {[](DenseWorkspaceOptions* o) { o->images.num_threads = 0; }, "ImageWriteOptions::num_threads"},
      {[](DenseWorkspaceOptions* o) { o->images.jpeg_quality = -1; }, "ImageWriteOptions::jpeg_quality"},
      {[](DenseWorkspaceOptions* o) { o->images.jpeg_quality = 101; }, "ImageWriteOptions::jpeg_quality"},
      {[](DenseWorkspaceOptions* o) { o->openmvs_version = kOpenMvsNewestVersion + 1; },
       "DenseWorkspaceOptions::openmvs_version"},
  });
}

TEST(ExportOptions, UnclampedScalesAndEveryOpenMvsVersionPass) {
  // A minimum of 0 and a maximum of infinity clamp nothing; equal bounds fix the scale.
  UndistortOptions unclamped;
  unclamped.min_focal_scale = 0.0;
  unclamped.max_focal_scale = kInf;
  EXPECT_EQ(CheckMessage(unclamped), "");
  UndistortOptions fixed;
  fixed.min_focal_scale = fixed.max_focal_scale = 1.0;
  EXPECT_EQ(CheckMessage(fixed), "");
  for (uint32_t version = 0; version <= kOpenMvsNewestVersion; ++version) {
    DenseWorkspaceOptions options;
    options.openmvs_version = version;
    options.images.jpeg_quality = 0;
    EXPECT_EQ(CheckMessage(options), "") << version;
  }
}

TEST(ExportOptions, EntryFunctionsRefuseBadOptionsBeforeAnyWork) {
  UndistortOptions undistort;
  undistort.min_focal_scale = 3.0;  // above max_focal_scale: std::clamp's precondition
  const CameraIntrinsics camera(CameraModel::kPinholeRadialK1, 320, 240, {300.0, 159.5, 119.5, -0.2});
  EXPECT_THROW(UndistortedIntrinsics(camera, undistort), std::invalid_argument);
  EXPECT_THROW(UndistortModel(SfmData(), undistort), std::invalid_argument);

  ImageWriteOptions images;
  images.jpeg_quality = 200;
  EXPECT_THROW(WriteUndistortedImages(SfmData(), UndistortedModel(), "/nonexistent/prunesfm/images",
                                      "/nonexistent/prunesfm/out", images),
               std::invalid_argument);

  DenseWorkspaceOptions workspace;
  workspace.images.num_threads = 0;
  const fs::path output = fs::temp_directory_path() / "prunesfm_export_options_never_written";
  EXPECT_THROW(WriteColmapUndistortedWorkspace(SfmData(), "/nonexistent/prunesfm/images", output, workspace),
               std::invalid_argument);
  EXPECT_THROW(WriteOpenMvsWorkspace(SfmData(), "/nonexistent/prunesfm/images", output, workspace),
               std::invalid_argument);
  EXPECT_FALSE(fs::exists(output));
}

}  // namespace
}  // namespace sfm_pruning
