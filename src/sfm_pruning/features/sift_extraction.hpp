// SIFT keypoints and descriptors with OpenCV's cv::SIFT (the patent expired in 2020; OpenCV 4.4+
// ships it in features2d), converted to the project's FeatureSet: pixel positions in the full
// image (OpenMVG convention, top-left pixel centre at 0, 0), scale = the keypoint's Gaussian
// sigma, orientation in radians, 128-byte descriptors (RootSIFT optionally).
#pragma once

#include <map>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "sfm_pruning/sfm/features.hpp"
#include "sfm_pruning/sfm/sfm_data.hpp"
#include "sfm_pruning/util/progress.hpp"

namespace sfm_pruning {

struct SiftOptions {
  // The strongest responses are kept. OpenCV counts every orientation of a keypoint, COLMAP caps its
  // 8192 before the extra orientations: on fountain-P11 COLMAP's default gives 10500-13000
  // descriptors per image, as many as this cap, and as many verified inliers (docs/frontend.md).
  int max_features = 12288;
  // Larger images are downscaled so that max(w, h) <= this. COLMAP uses 3200; at that size the 8192
  // strongest responses of a 6-12 Mpx photo are fine-scale texture that other views do not
  // repeat (Sceaux Castle lost a view), and 1600 gives as many or more verified inliers with the
  // same accuracy, 4x faster (docs/frontend.md).
  int max_image_size = 1600;
  bool root_sift = true;       // RootSIFT (Arandjelovic & Zisserman 2012): sqrt of the L1-normalised descriptor
  // OpenCV's contrastThreshold: a DoG extremum is kept when |D| >= this / num_octave_layers on the
  // [0, 1] image; 0.02 gives 0.0067, COLMAP's (VLFeat's) peak threshold. OpenCV's default 0.04
  // keeps half as many weak features.
  double contrast_threshold = 0.02;
  double edge_threshold = 10.0;
  int num_octave_layers = 3;
  int num_threads = 1;         // images extracted in parallel

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

// One image (8-bit grey). Features are sorted by decreasing response, at most max_features.
FeatureSet ExtractSift(const cv::Mat& gray, const SiftOptions& options);

struct FeatureExtractionReport {
  std::map<IndexT, std::string> failed_views;  // views whose image no longer decodes, with the reason
  size_t total_features = 0;
};

// Every view of `scene` (images under scene.root_path). A view whose image does not decode gets
// no features and is listed in the report. Progress stage: "extracting features".
FeaturesPerView ExtractFeatures(const SfmData& scene, const SiftOptions& options, FeatureExtractionReport* report,
                                const ProgressCallback& progress = {});

}  // namespace sfm_pruning
