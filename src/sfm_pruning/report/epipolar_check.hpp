// The paper's epipolar check (teaser figure): a point in a reference image and, in other images
// that see the same region, its epipolar curve under the reconstruction's poses. A consistent
// reconstruction puts the curve through the point's true correspondence; a folded one (twin
// structures merged) puts it through the twin or nowhere near.
//
// The curve is the epipolar line traced in the undistorted normalised plane of the other camera
// and mapped to pixels through its distortion, so it bends with the lens like the image does.
// With ground truth the curve of the true poses is drawn too (green): where it crosses the
// estimated one is where the estimate agrees with the truth for this point.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sfm_pruning/sfm/sfm_data.hpp"

namespace sfm_pruning {

using PixelPolyline = std::vector<Eigen::Vector2d>;

// Pieces of the epipolar curve of `pixel_a` (camera a) inside image b (pixels of b, PruneSfM's
// pixel convention), sampled at `samples` points along the line. Empty when the line misses the
// image or the bearing passes through b's centre. Pinhole-family cameras only (throws Error for
// spherical ones).
std::vector<PixelPolyline> EpipolarCurve(const CameraIntrinsics& intrinsics_a, const Pose& pose_a,
                                         const CameraIntrinsics& intrinsics_b, const Pose& pose_b,
                                         const Eigen::Vector2d& pixel_a, int samples = 240);

// Distance in pixels from `pixel` to the nearest piece of `curve` (infinity when it is empty).
double DistanceToCurve(const std::vector<PixelPolyline>& curve, const Eigen::Vector2d& pixel);

struct EpipolarCheckOptions {
  size_t max_other_views = 3;
  // Landmarks observed within this fraction of the image diagonal from the point define the
  // region whose other observers are shown.
  double region_fraction = 0.08;
  // An observation within this many pixels of the point is "the point's feature": its track's
  // observations are marked in the other images.
  double feature_radius_px = 12.0;

  // Throws std::invalid_argument naming the first field out of range (util/option_checks.hpp).
  void Check() const;
};

struct EpipolarPanel {
  std::string image;  // RelativeImagePath
  bool registered = false;
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<PixelPolyline> estimated;  // empty when not registered
  std::vector<PixelPolyline> truth;      // empty without ground truth for both images
  std::optional<Eigen::Vector2d> matched_feature;  // observation of the point's track here
};

struct EpipolarCheck {
  EpipolarPanel reference;  // no curves
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
  std::vector<EpipolarPanel> others;
};

// A point worth checking in `image`: the observation of its longest track near the image centre
// (ties: closer to the centre, then lower landmark id); the image centre when it has none.
// Throws Error when the model has no registered view of that name.
Eigen::Vector2d ChooseCheckPoint(const SfmData& model, const std::string& image);

// Up to `count` registered images spread evenly over the image-name order.
std::vector<std::string> ChooseCheckImages(const SfmData& model, size_t count);

// Registered images (other than `image`) that observe the most landmarks of the region around
// `point` in `image`; when none does, those sharing the most landmarks with it. Name order on ties.
std::vector<std::string> ImagesSeeingRegion(const SfmData& model, const std::string& image,
                                            const Eigen::Vector2d& point, const EpipolarCheckOptions& options = {});

// The check for `point` in `image` against `others` (by name; images the model did not register
// get an empty panel). `truth` (matched by file basename) adds the true curves. Throws Error
// when `image` is not registered in `model`, the point lies outside it, or an image of `others`
// is not a view of the model.
EpipolarCheck ComputeEpipolarCheck(const SfmData& model, const std::string& image, const Eigen::Vector2d& point,
                                   const std::vector<std::string>& others, const SfmData* truth = nullptr,
                                   const EpipolarCheckOptions& options = {});

}  // namespace sfm_pruning
