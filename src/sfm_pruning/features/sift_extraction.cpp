#include "sfm_pruning/features/sift_extraction.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>

#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

#include "sfm_pruning/features/image_decoding.hpp"
#include "sfm_pruning/util/option_checks.hpp"
#include "sfm_pruning/util/parallel_for.hpp"

namespace sfm_pruning {
namespace {

// OpenCV scales its descriptors so that a unit-norm histogram maps to [0, 512] before the cast
// to bytes; RootSIFT values sqrt(p) with sum(p) = 1 lie in [0, 1] and take the same factor.
constexpr float kDescriptorScale = 512.f;

Descriptor ToBytes(const float* values, bool root_sift) {
  Descriptor out{};
  if (root_sift) {
    float l1 = 0.f;
    for (int d = 0; d < kDescriptorSize; ++d) l1 += std::abs(values[d]);
    const float inv = l1 > 0.f ? 1.f / l1 : 0.f;
    for (int d = 0; d < kDescriptorSize; ++d) {
      out[d] = static_cast<uint8_t>(std::min(255.f, std::round(kDescriptorScale * std::sqrt(std::abs(values[d]) * inv))));
    }
  } else {
    for (int d = 0; d < kDescriptorSize; ++d) out[d] = static_cast<uint8_t>(std::clamp(std::round(values[d]), 0.f, 255.f));
  }
  return out;
}

// OpenCV's own parallel loops would compete with our workers for the cores: while images are
// extracted in parallel, OpenCV runs single-threaded; the previous setting is restored after.
class ScopedOpenCvThreads {
 public:
  explicit ScopedOpenCvThreads(int threads) : previous_(cv::getNumThreads()) { cv::setNumThreads(threads); }
  ~ScopedOpenCvThreads() { cv::setNumThreads(previous_); }
  ScopedOpenCvThreads(const ScopedOpenCvThreads&) = delete;
  ScopedOpenCvThreads& operator=(const ScopedOpenCvThreads&) = delete;

 private:
  int previous_;
};

}  // namespace

FeatureSet ExtractSift(const cv::Mat& gray, const SiftOptions& options) {
  options.Check();
  cv::Mat image = gray;
  double scale = 1.0;  // full-image pixels per pixel of `image`
  const int max_side = std::max(gray.cols, gray.rows);
  if (options.max_image_size > 0 && max_side > options.max_image_size) {
    scale = static_cast<double>(max_side) / options.max_image_size;
    const cv::Size size(std::max(1, static_cast<int>(std::lround(gray.cols / scale))),
                        std::max(1, static_cast<int>(std::lround(gray.rows / scale))));
    cv::resize(gray, image, size, 0, 0, cv::INTER_AREA);
  }
  const double scale_x = static_cast<double>(gray.cols) / image.cols;
  const double scale_y = static_cast<double>(gray.rows) / image.rows;

  cv::Ptr<cv::SIFT> sift = cv::SIFT::create(options.max_features, options.num_octave_layers,
                                            options.contrast_threshold, options.edge_threshold);
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  sift->detectAndCompute(image, cv::noArray(), keypoints, descriptors);

  // Strongest first; ties broken by position so the order is deterministic.
  std::vector<size_t> order(keypoints.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    const cv::KeyPoint& ka = keypoints[a];
    const cv::KeyPoint& kb = keypoints[b];
    if (ka.response != kb.response) return ka.response > kb.response;
    if (ka.pt.y != kb.pt.y) return ka.pt.y < kb.pt.y;
    if (ka.pt.x != kb.pt.x) return ka.pt.x < kb.pt.x;
    return ka.angle < kb.angle;
  });
  if (options.max_features > 0 && order.size() > static_cast<size_t>(options.max_features)) {
    order.resize(static_cast<size_t>(options.max_features));
  }

  FeatureSet features;
  features.keypoints.reserve(order.size());
  features.descriptors.reserve(order.size());
  for (size_t k : order) {
    const cv::KeyPoint& kp = keypoints[k];
    Keypoint out;
    // Pixel centres: (0, 0) is the centre of the top-left pixel in both images, so the full-image
    // position of x is (x + 0.5) * scale - 0.5.
    out.x = static_cast<float>((kp.pt.x + 0.5) * scale_x - 0.5);
    out.y = static_cast<float>((kp.pt.y + 0.5) * scale_y - 0.5);
    out.scale = static_cast<float>(0.5 * kp.size * scale);  // OpenCV's size is twice the sigma
    out.orientation = static_cast<float>(kp.angle * M_PI / 180.0);
    features.keypoints.push_back(out);
    features.descriptors.push_back(ToBytes(descriptors.ptr<float>(static_cast<int>(k)), options.root_sift));
  }
  return features;
}

FeaturesPerView ExtractFeatures(const SfmData& scene, const SiftOptions& options, FeatureExtractionReport* report,
                                const ProgressCallback& progress) {
  options.Check();
  std::vector<IndexT> view_ids;
  for (const auto& [view_id, view] : scene.views) view_ids.push_back(view_id);
  std::vector<FeatureSet> results(view_ids.size());
  std::vector<std::string> problems(view_ids.size());
  const int workers = std::max(1, std::min<int>(options.num_threads, static_cast<int>(view_ids.size())));
  // One image at a time: let OpenCV parallelise inside it; several: one image per worker.
  const ScopedOpenCvThreads opencv_threads(workers > 1 ? 1 : std::max(1, options.num_threads));
  ParallelFor(
      view_ids.size(), workers,
      [&](size_t k) {
        const View& view = scene.views.at(view_ids[k]);
        const DecodedImage image = DecodeGrayImage(std::filesystem::path(scene.root_path) / view.RelativeImagePath());
        if (!image.ok()) {
          problems[k] = image.problem;
          return;
        }
        results[k] = ExtractSift(image.pixels, options);
      },
      progress, "extracting features");

  FeatureExtractionReport local;
  FeatureExtractionReport& out = report != nullptr ? *report : local;
  out = {};
  FeaturesPerView features;
  for (size_t k = 0; k < view_ids.size(); ++k) {
    if (!problems[k].empty()) {
      out.failed_views[view_ids[k]] = problems[k];
      continue;
    }
    out.total_features += results[k].size();
    features[view_ids[k]] = std::move(results[k]);
  }
  return features;
}

void SiftOptions::Check() const {
  // 0 is OpenCV's "no cap" for the feature count and ExtractSift's "no downscaling" for the size.
  RequireAtLeast(max_features, 0, "SiftOptions::max_features (0: no cap)");
  RequireAtLeast(max_image_size, 0, "SiftOptions::max_image_size (0: full size)");
  // 0 keeps every DoG extremum; a negative threshold would too, so it can only be a mistake.
  RequireAtLeast(contrast_threshold, 0.0, "SiftOptions::contrast_threshold");
  // The largest ratio of principal curvatures kept; an infinite one fails OpenCV's test (inf < inf).
  RequirePositiveFinite(edge_threshold, "SiftOptions::edge_threshold");
  RequireAtLeast(num_octave_layers, 1, "SiftOptions::num_octave_layers");
  RequireAtLeast(num_threads, 1, "SiftOptions::num_threads");
}

}  // namespace sfm_pruning
