#include "sfm_pruning/report/epipolar_check.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>

#include "sfm_pruning/geometry/epipolar_geometry.hpp"
#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/option_checks.hpp"

namespace sfm_pruning {
namespace {

const View* FindView(const SfmData& model, const std::string& image) {
  for (const auto& [id, view] : model.views) {
    if (view.RelativeImagePath() == image) return &view;
  }
  return nullptr;
}

// Ground truth lists cameras by file name only (eval/camera_matching.hpp matches basenames too).
const View* FindViewByBasename(const SfmData& model, const std::string& image) {
  const std::string name = std::filesystem::path(image).filename().string();
  for (const auto& [id, view] : model.views) {
    if (std::filesystem::path(view.filename).filename().string() == name) return &view;
  }
  return nullptr;
}

const View& RegisteredView(const SfmData& model, const std::string& image) {
  const View* view = FindView(model, image);
  if (view == nullptr) throw Error("image " + image + " is not in the model");
  if (!model.IsPosed(*view)) throw Error("image " + image + " is not registered in the model");
  return *view;
}

Eigen::Vector2d ImageSize(const SfmData& model, const View& view) {
  if (view.width > 0 && view.height > 0) return {view.width, view.height};
  const CameraIntrinsics& intrinsics = model.IntrinsicsOf(view);
  return {intrinsics.width(), intrinsics.height()};
}

// Clips the line a x + b y + c = 0 to the box [low, high]; false when it misses the box.
bool ClipLine(const Eigen::Vector3d& line, const Eigen::Vector2d& low, const Eigen::Vector2d& high, Eigen::Vector2d* p,
              Eigen::Vector2d* q) {
  std::vector<Eigen::Vector2d> hits;
  if (std::abs(line.y()) > 1e-15) {  // crossings of the vertical sides
    for (double x : {low.x(), high.x()}) {
      const double y = -(line.x() * x + line.z()) / line.y();
      if (y >= low.y() && y <= high.y()) hits.emplace_back(x, y);
    }
  }
  if (std::abs(line.x()) > 1e-15) {  // crossings of the horizontal sides
    for (double y : {low.y(), high.y()}) {
      const double x = -(line.y() * y + line.z()) / line.x();
      if (x >= low.x() && x <= high.x()) hits.emplace_back(x, y);
    }
  }
  if (hits.size() < 2) return false;
  // The two hits farthest apart (a corner can be hit twice).
  double best = -1.0;
  for (size_t i = 0; i < hits.size(); ++i) {
    for (size_t j = i + 1; j < hits.size(); ++j) {
      const double d = (hits[i] - hits[j]).squaredNorm();
      if (d > best) {
        best = d;
        *p = hits[i];
        *q = hits[j];
      }
    }
  }
  return best > 0.0;
}

EpipolarPanel EmptyPanel(const SfmData& model, const std::string& image) {
  EpipolarPanel panel;
  panel.image = image;
  if (const View* view = FindView(model, image)) {
    panel.registered = model.IsPosed(*view);
    const Eigen::Vector2d size = view->width > 0 ? Eigen::Vector2d(view->width, view->height)
                                 : model.intrinsics.count(view->id_intrinsic)
                                     ? ImageSize(model, *view)
                                     : Eigen::Vector2d::Zero();
    panel.width = static_cast<uint32_t>(size.x());
    panel.height = static_cast<uint32_t>(size.y());
  }
  return panel;
}

}  // namespace

std::vector<PixelPolyline> EpipolarCurve(const CameraIntrinsics& intrinsics_a, const Pose& pose_a,
                                         const CameraIntrinsics& intrinsics_b, const Pose& pose_b,
                                         const Eigen::Vector2d& pixel_a, int samples) {
  if (!IsPinholeFamily(intrinsics_a.model()) || !IsPinholeFamily(intrinsics_b.model())) {
    throw Error("epipolar curves need pinhole-family cameras, not " + CameraModelName(intrinsics_b.model()));
  }
  const Eigen::Vector3d bearing = intrinsics_a.Unproject(pixel_a);
  const Eigen::Vector3d line = EssentialMatrix(RelativePoseBetween(pose_a, pose_b)) * bearing;
  if (line.head<2>().norm() < 1e-12) return {};
  // The image of b in its normalised plane: the box around its undistorted border, with a margin
  // so that the curve reaches the edges after distortion.
  const double w = intrinsics_b.width(), h = intrinsics_b.height();
  Eigen::Vector2d low = intrinsics_b.PixelToNormalized({-0.5, -0.5}), high = low;
  constexpr int kBorderSamples = 32;
  for (int k = 0; k <= kBorderSamples; ++k) {
    const double s = static_cast<double>(k) / kBorderSamples;
    for (const Eigen::Vector2d& pixel : {Eigen::Vector2d(s * w - 0.5, -0.5), Eigen::Vector2d(s * w - 0.5, h - 0.5),
                                         Eigen::Vector2d(-0.5, s * h - 0.5), Eigen::Vector2d(w - 0.5, s * h - 0.5)}) {
      const Eigen::Vector2d n = intrinsics_b.PixelToNormalized(pixel);
      low = low.cwiseMin(n);
      high = high.cwiseMax(n);
    }
  }
  const Eigen::Vector2d margin = (high - low) * 0.05;
  Eigen::Vector2d p = Eigen::Vector2d::Zero(), q = Eigen::Vector2d::Zero();
  if (!ClipLine(line, low - margin, high + margin, &p, &q)) return {};
  std::vector<PixelPolyline> pieces;
  PixelPolyline current;
  for (int k = 0; k <= samples; ++k) {
    const Eigen::Vector2d n = p + (q - p) * (static_cast<double>(k) / samples);
    const Eigen::Vector2d pixel = intrinsics_b.NormalizedToPixel(n);
    if (pixel.x() >= -0.5 && pixel.y() >= -0.5 && pixel.x() <= w - 0.5 && pixel.y() <= h - 0.5) {
      current.push_back(pixel);
    } else if (!current.empty()) {
      if (current.size() >= 2) pieces.push_back(current);
      current.clear();
    }
  }
  if (current.size() >= 2) pieces.push_back(current);
  return pieces;
}

double DistanceToCurve(const std::vector<PixelPolyline>& curve, const Eigen::Vector2d& pixel) {
  double best = std::numeric_limits<double>::infinity();
  for (const PixelPolyline& piece : curve) {
    for (size_t k = 0; k + 1 < piece.size(); ++k) {
      const Eigen::Vector2d d = piece[k + 1] - piece[k];
      const double squared = d.squaredNorm();
      const double t = squared > 0.0 ? std::clamp((pixel - piece[k]).dot(d) / squared, 0.0, 1.0) : 0.0;
      best = std::min(best, (piece[k] + t * d - pixel).norm());
    }
  }
  return best;
}

Eigen::Vector2d ChooseCheckPoint(const SfmData& model, const std::string& image) {
  const View& view = RegisteredView(model, image);
  const Eigen::Vector2d size = ImageSize(model, view);
  const Eigen::Vector2d center = (size - Eigen::Vector2d::Ones()) / 2.0;
  const double central_radius = 0.3 * size.norm();
  Eigen::Vector2d best = center;
  size_t best_length = 0;
  double best_distance = 0.0;
  for (const auto& [id, landmark] : model.structure) {
    const auto it = landmark.observations.find(view.id_view);
    if (it == landmark.observations.end()) continue;
    const double distance = (it->second.x - center).norm();
    if (distance > central_radius) continue;
    const size_t length = landmark.observations.size();
    if (length > best_length || (length == best_length && distance < best_distance)) {
      best = it->second.x;
      best_length = length;
      best_distance = distance;
    }
  }
  return best;
}

std::vector<std::string> ChooseCheckImages(const SfmData& model, size_t count) {
  std::vector<std::string> registered;
  for (const auto& [id, view] : model.views) {
    if (model.IsPosed(view)) registered.push_back(view.RelativeImagePath());
  }
  std::sort(registered.begin(), registered.end());
  std::vector<std::string> chosen;
  count = std::min(count, registered.size());
  for (size_t k = 0; k < count; ++k) {
    chosen.push_back(registered[(2 * k + 1) * registered.size() / (2 * count)]);
  }
  return chosen;
}

std::vector<std::string> ImagesSeeingRegion(const SfmData& model, const std::string& image,
                                            const Eigen::Vector2d& point, const EpipolarCheckOptions& options) {
  options.Check();
  const View& view = RegisteredView(model, image);
  const double radius = options.region_fraction * ImageSize(model, view).norm();
  std::map<IndexT, size_t> in_region, shared;
  for (const auto& [id, landmark] : model.structure) {
    const auto it = landmark.observations.find(view.id_view);
    if (it == landmark.observations.end()) continue;
    const bool near = (it->second.x - point).norm() <= radius;
    for (const auto& [other, observation] : landmark.observations) {
      if (other == view.id_view || !model.IsPosed(other)) continue;
      ++shared[other];
      if (near) ++in_region[other];
    }
  }
  const std::map<IndexT, size_t>& counts = in_region.empty() ? shared : in_region;
  std::vector<std::pair<std::string, size_t>> ranked;
  for (const auto& [other, count] : counts) ranked.emplace_back(model.views.at(other).RelativeImagePath(), count);
  std::sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) {
    return a.second != b.second ? a.second > b.second : a.first < b.first;
  });
  std::vector<std::string> images;
  for (size_t k = 0; k < std::min(options.max_other_views, ranked.size()); ++k) images.push_back(ranked[k].first);
  std::sort(images.begin(), images.end());
  return images;
}

EpipolarCheck ComputeEpipolarCheck(const SfmData& model, const std::string& image, const Eigen::Vector2d& point,
                                   const std::vector<std::string>& others, const SfmData* truth,
                                   const EpipolarCheckOptions& options) {
  options.Check();
  const View& view = RegisteredView(model, image);
  const Eigen::Vector2d size = ImageSize(model, view);
  if (point.x() < -0.5 || point.y() < -0.5 || point.x() > size.x() - 0.5 || point.y() > size.y() - 0.5) {
    throw Error("point (" + std::to_string(point.x()) + ", " + std::to_string(point.y()) + ") is outside image " +
                image + " (" + std::to_string(static_cast<int>(size.x())) + " x " +
                std::to_string(static_cast<int>(size.y())) + ")");
  }
  EpipolarCheck check;
  check.point = point;
  check.reference = EmptyPanel(model, image);

  // The point's own feature: the nearest observation within feature_radius_px.
  const Landmark* track = nullptr;
  double nearest = options.feature_radius_px;
  for (const auto& [id, landmark] : model.structure) {
    const auto it = landmark.observations.find(view.id_view);
    if (it == landmark.observations.end()) continue;
    const double distance = (it->second.x - point).norm();
    if (distance <= nearest) {
      nearest = distance;
      track = &landmark;
    }
  }
  const View* true_reference = truth ? FindViewByBasename(*truth, image) : nullptr;
  if (true_reference != nullptr && !truth->IsPosed(*true_reference)) true_reference = nullptr;

  for (const std::string& other : others) {
    const View* other_view = FindView(model, other);
    if (other_view == nullptr) throw Error("image " + other + " is not in the model");
    EpipolarPanel panel = EmptyPanel(model, other);
    if (panel.registered) {
      panel.estimated = EpipolarCurve(model.IntrinsicsOf(view), model.PoseOf(view), model.IntrinsicsOf(*other_view),
                                      model.PoseOf(*other_view), point);
      if (track != nullptr) {
        const auto it = track->observations.find(other_view->id_view);
        if (it != track->observations.end()) panel.matched_feature = it->second.x;
      }
    }
    const View* true_other = truth ? FindViewByBasename(*truth, other) : nullptr;
    if (true_reference != nullptr && true_other != nullptr && truth->IsPosed(*true_other)) {
      panel.truth = EpipolarCurve(truth->IntrinsicsOf(*true_reference), truth->PoseOf(*true_reference),
                                  truth->IntrinsicsOf(*true_other), truth->PoseOf(*true_other), point);
      if (panel.width == 0) {
        panel.width = truth->IntrinsicsOf(*true_other).width();
        panel.height = truth->IntrinsicsOf(*true_other).height();
      }
    }
    check.others.push_back(std::move(panel));
  }
  return check;
}

void EpipolarCheckOptions::Check() const {
  // Any max_other_views is valid (0 chooses no other image). A radius of 0 keeps what lies at the
  // point itself; a negative one would keep nothing.
  RequireAtLeast(region_fraction, 0.0, "EpipolarCheckOptions::region_fraction");
  RequireAtLeast(feature_radius_px, 0.0, "EpipolarCheckOptions::feature_radius_px");
}

}  // namespace sfm_pruning
