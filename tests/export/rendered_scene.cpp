#include "export/rendered_scene.hpp"

#include <cmath>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>

namespace sfm_pruning::testing {

cv::Vec3d ColorOfRay(const Eigen::Vector3d& world_direction) {
  const Eigen::Vector3d d = world_direction.normalized();
  return {128 + 90 * std::sin(9 * d.x() + 1), 128 + 90 * std::sin(7 * d.y() - 2 * d.x()),
          128 + 90 * std::cos(6 * d.x() + 5 * d.y())};
}

namespace {

// Pixel -> camera ray. Inverting a lens distortion is iterative and slow in the sanitizer build,
// so distorted cameras are inverted on a grid of kGridStep pixels and the rays interpolated
// bilinearly in between: the ray field is smooth, and the error (~1e-5 rad for the test lenses)
// moves the rendered colour by < 0.05 grey levels. Closed-form cameras are inverted per pixel.
constexpr int kGridStep = 8;

class RayField {
 public:
  explicit RayField(const CameraIntrinsics& camera) : camera_(camera) {
    exact_ = camera.model() == CameraModel::kSpherical || !camera.HasDistortion();
    if (exact_) return;
    columns_ = (static_cast<int>(camera.width()) - 1) / kGridStep + 2;
    rows_ = (static_cast<int>(camera.height()) - 1) / kGridStep + 2;
    nodes_.resize(static_cast<size_t>(columns_ * rows_));
    for (int j = 0; j < rows_; ++j) {
      for (int i = 0; i < columns_; ++i) {
        nodes_[j * columns_ + i] = camera.Unproject(Eigen::Vector2d(i * kGridStep, j * kGridStep));
      }
    }
  }

  Eigen::Vector3d operator()(int u, int v) const {
    if (exact_) return camera_.Unproject(Eigen::Vector2d(u, v));
    const int i = u / kGridStep, j = v / kGridStep;
    const double a = static_cast<double>(u - i * kGridStep) / kGridStep;
    const double b = static_cast<double>(v - j * kGridStep) / kGridStep;
    const auto node = [&](int di, int dj) { return nodes_[(j + dj) * columns_ + i + di]; };
    return ((1 - b) * ((1 - a) * node(0, 0) + a * node(1, 0)) + b * ((1 - a) * node(0, 1) + a * node(1, 1)))
        .normalized();
  }

 private:
  const CameraIntrinsics& camera_;
  bool exact_ = true;
  int columns_ = 0, rows_ = 0;
  std::vector<Eigen::Vector3d> nodes_;
};

}  // namespace

cv::Mat RenderView(const SfmData& data, IndexT view_id) {
  const View& view = data.views.at(view_id);
  const CameraIntrinsics& camera = data.IntrinsicsOf(view);
  const Pose& pose = data.PoseOf(view);
  const RayField rays(camera);
  cv::Mat image(static_cast<int>(camera.height()), static_cast<int>(camera.width()), CV_8UC3);
  for (int v = 0; v < image.rows; ++v) {
    for (int u = 0; u < image.cols; ++u) {
      const cv::Vec3d color = ColorOfRay(pose.rotation.transpose() * rays(u, v));
      image.at<cv::Vec3b>(v, u) =
          cv::Vec3b(cv::saturate_cast<uint8_t>(color[0]), cv::saturate_cast<uint8_t>(color[1]),
                    cv::saturate_cast<uint8_t>(color[2]));
    }
  }
  return image;
}

SfmData MakeRenderedScene(const CameraIntrinsics& camera, const std::filesystem::path& image_dir) {
  SfmData data;
  data.root_path = image_dir.string();
  data.intrinsics[0] = camera;
  for (IndexT v = 0; v < 3; ++v) {
    const double angle = -0.3 + 0.3 * v;
    const Eigen::Vector3d center(5 * std::sin(angle), 0.2 * v - 0.2, -5 * std::cos(angle));
    const Eigen::Vector3d z = (-center).normalized();
    const Eigen::Vector3d x = Eigen::Vector3d::UnitY().cross(z).normalized();
    Eigen::Matrix3d R;
    R << x.transpose(), z.cross(x).transpose(), z.transpose();
    data.poses[v] = Pose(R, center);
    View view;
    view.id_view = view.id_pose = v;
    view.id_intrinsic = 0;
    view.filename = "view" + std::to_string(v) + ".png";
    view.width = camera.width();
    view.height = camera.height();
    data.views[v] = view;
  }
  for (IndexT k = 0; k < 40; ++k) {
    Landmark landmark;
    landmark.X = {1.2 * std::sin(1.7 * k), 0.9 * std::cos(2.3 * k), 0.8 * std::sin(0.9 * k + 0.4)};
    for (const auto& [v, view] : data.views) {
      landmark.observations[v] = {camera.Project(data.poses[v].ToCamera(landmark.X)), k};
    }
    data.structure[k] = landmark;
  }
  std::filesystem::create_directories(image_dir);
  for (const auto& [v, view] : data.views)
    cv::imwrite((image_dir / view.filename).string(), RenderView(data, v));
  return data;
}

}  // namespace sfm_pruning::testing
