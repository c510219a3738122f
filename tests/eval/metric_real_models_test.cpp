// The strongest check of the metric: COLMAP's own temple reconstructions against the Middlebury
// ground truth must give the AUCs published with the files (../shared/formats/colmap/README.md).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "sfm_pruning/eval/model_evaluation.hpp"
#include "sfm_pruning/io/model_io.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning {
namespace {

// The README rounds to one decimal.
constexpr double kPublishedRounding = 0.1;
constexpr const char* kTempleTruth = "datasets/middlebury/templeSparseRing/gt_cameras.txt";

struct PublishedRun {
  size_t num_registered_images;
  size_t num_failed_pairs;
  std::vector<double> auc_percent;  // at 3, 5, 10 degrees
};

void ExpectPublishedRun(const std::filesystem::path& model, const std::filesystem::path& truth,
                        const PublishedRun& published) {
  const EvaluationReport report = EvaluateModel(ReadModel(model), ReadModel(truth));
  EXPECT_EQ(report.num_ground_truth_images, 16u);
  EXPECT_EQ(report.num_registered_images, published.num_registered_images);
  EXPECT_EQ(report.num_failed_pairs, published.num_failed_pairs);
  ASSERT_EQ(report.auc.size(), published.auc_percent.size());
  for (size_t k = 0; k < report.auc.size(); ++k) {
    EXPECT_NEAR(report.auc[k].auc_percent, published.auc_percent[k], kPublishedRounding)
        << "AUC@" << report.auc[k].threshold_deg;
  }
}

TEST(RealModels, Colmap38IncrementalTemple) {
  PRUNESFM_REQUIRE_SHARED(kTempleTruth, truth_path);
  PRUNESFM_REQUIRE_SHARED("formats/colmap/colmap-3.8/sparse_bin", model_path);
  // 3 unregistered images: 3 * 15 - 3 pairs among themselves = 42 of 120 pairs fail.
  ExpectPublishedRun(model_path, truth_path, {13, 42, {49.5, 55.4, 59.8}});
}

TEST(RealModels, Colmap411GlobalTemple) {
  PRUNESFM_REQUIRE_SHARED(kTempleTruth, truth_path);
  PRUNESFM_REQUIRE_SHARED("formats/colmap/colmap-4.1.1/sparse_bin", model_path);
  ExpectPublishedRun(model_path, truth_path, {16, 0, {70.4, 81.9, 90.5}});
}

TEST(RealModels, TextAndBinaryEncodingsAgree) {
  PRUNESFM_REQUIRE_SHARED(kTempleTruth, truth_path);
  PRUNESFM_REQUIRE_SHARED("formats/colmap/colmap-4.1.1/sparse_txt", text_path);
  PRUNESFM_REQUIRE_SHARED("formats/colmap/colmap-4.1.1/sparse_bin", binary_path);
  const SfmData truth = ReadModel(truth_path);
  const EvaluationReport text = EvaluateModel(ReadModel(text_path), truth);
  const EvaluationReport binary = EvaluateModel(ReadModel(binary_path), truth);
  ASSERT_EQ(text.auc.size(), binary.auc.size());
  // images.txt prints 17 significant digits, so both encodings carry the same poses.
  for (size_t k = 0; k < text.auc.size(); ++k) EXPECT_NEAR(text.auc[k].auc_percent, binary.auc[k].auc_percent, 1e-9);
}

TEST(RealModels, OpenMvgReconstructionAgainstItself) {
  PRUNESFM_REQUIRE_SHARED("formats/openmvg/sceaux_castle/reconstruction_global/sfm_data.json", sfm_data_path);
  const SfmData model = ReadModel(sfm_data_path);
  const EvaluationReport report = EvaluateModel(model, model);
  EXPECT_EQ(report.num_registered_images, 11u);
  for (const AucAtThreshold& auc : report.auc) EXPECT_NEAR(auc.auc_percent, 100.0, 1e-4);
  ASSERT_TRUE(report.alignment.has_value());
  EXPECT_EQ(report.alignment->num_inliers, 11u);
  EXPECT_NEAR(report.alignment->transform.scale, 1.0, 1e-9);
}

}  // namespace
}  // namespace sfm_pruning
