#include "sfm_pruning/export/point_colors.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "sfm_pruning/export/image_files.hpp"
#include "sfm_pruning/util/parallel_for.hpp"

namespace sfm_pruning {
namespace {

// Bilinear BGR sample at a pixel position (centre of the top-left pixel at (0, 0)); false
// outside the pixel centres' frame.
bool SampleBgr(const cv::Mat& image, const Eigen::Vector2d& x, Eigen::Vector3d* bgr) {
  if (!(x.x() >= 0 && x.y() >= 0 && x.x() <= image.cols - 1 && x.y() <= image.rows - 1)) return false;
  const int u0 = std::min(static_cast<int>(x.x()), image.cols - 2 < 0 ? 0 : image.cols - 2);
  const int v0 = std::min(static_cast<int>(x.y()), image.rows - 2 < 0 ? 0 : image.rows - 2);
  const int u1 = std::min(u0 + 1, image.cols - 1);
  const int v1 = std::min(v0 + 1, image.rows - 1);
  const double a = x.x() - u0, b = x.y() - v0;
  const auto at = [&](int v, int u) {
    const cv::Vec3b& p = image.at<cv::Vec3b>(v, u);
    return Eigen::Vector3d(p[0], p[1], p[2]);
  };
  *bgr = (1 - b) * ((1 - a) * at(v0, u0) + a * at(v0, u1)) + b * ((1 - a) * at(v1, u0) + a * at(v1, u1));
  return true;
}

}  // namespace

void ColorLandmarksFromImages(SfmData* data, const std::filesystem::path& image_root, int num_threads,
                              const ProgressCallback& progress) {
  // Observations grouped by view: (landmark id, position).
  std::map<IndexT, std::vector<std::pair<IndexT, Eigen::Vector2d>>> by_view;
  for (const auto& [landmark_id, landmark] : data->structure) {
    for (const auto& [view_id, observation] : landmark.observations) {
      by_view[view_id].emplace_back(landmark_id, observation.x);
    }
  }
  std::vector<IndexT> views;
  for (const auto& [view_id, observations] : by_view) views.push_back(view_id);
  // Per view, the sampled colour of each of its observations (NaN outside the image).
  std::vector<std::vector<Eigen::Vector3d>> samples(views.size());
  ParallelFor(
      views.size(), num_threads,
      [&](size_t index) {
        const cv::Mat image = ReadColorImage(image_root / data->views.at(views[index]).RelativeImagePath());
        const auto& observations = by_view.at(views[index]);
        samples[index].resize(observations.size());
        for (size_t k = 0; k < observations.size(); ++k) {
          if (!SampleBgr(image, observations[k].second, &samples[index][k])) {
            samples[index][k].setConstant(std::nan(""));
          }
        }
      },
      progress, "sampling point colours");
  // Sums in view order, so the result is the same whatever the thread count.
  std::map<IndexT, std::pair<Eigen::Vector3d, int>> sums;
  for (size_t index = 0; index < views.size(); ++index) {
    const auto& observations = by_view.at(views[index]);
    for (size_t k = 0; k < observations.size(); ++k) {
      if (!samples[index][k].allFinite()) continue;
      auto& [sum, count] = sums.try_emplace(observations[k].first, Eigen::Vector3d::Zero(), 0).first->second;
      sum += samples[index][k];
      ++count;
    }
  }
  for (const auto& [landmark_id, sum_count] : sums) {
    const Eigen::Vector3d bgr = sum_count.first / sum_count.second;
    const auto channel = [&](int c) {
      return static_cast<uint8_t>(std::clamp(std::lround(bgr[c]), 0L, 255L));
    };
    data->structure.at(landmark_id).color = {channel(2), channel(1), channel(0)};
  }
}

}  // namespace sfm_pruning
