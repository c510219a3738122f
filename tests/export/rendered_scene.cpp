#include "export/rendered_scene.hpp"

#include <cmath>
#include <string>

#include <opencv2/imgcodecs.hpp>

namespace sfm_pruning::testing {

cv::Vec3d ColorOfRay(const Eigen::Vector3d& world_direction) {
  const Eigen::Vector3d d = world_direction.normalized();
  return {128 + 90 * std::sin(9 * d.x() + 1), 128 + 90 * std::sin(7 * d.y() - 2 * d.x()),
          128 + 90 * std::cos(6 * d.x() + 5 * d.y())};
}

cv::Mat RenderView(const SfmData& data, IndexT view_id) {
  const View& view = data.views.at(view_id);
  const CameraIntrinsics& camera = data.IntrinsicsOf(view);
  const Pose& pose = data.PoseOf(view);
  cv::Mat image(static_cast<int>(camera.height()), static_cast<int>(camera.width()), CV_8UC3);
  for (int v = 0; v < image.rows; ++v) {
    for (int u = 0; u < image.cols; ++u) {
      const Eigen::Vector3d ray = pose.rotation.transpose() * camera.Unproject(Eigen::Vector2d(u, v));
      const cv::Vec3d color = ColorOfRay(ray);
      image.at<cv::Vec3b>(v, u) = cv::Vec3b(cv::saturate_cast<uint8_t>(color[0]), cv::saturate_cast<uint8_t>(color[1]),
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
  for (const auto& [v, view] : data.views) cv::imwrite((image_dir / view.filename).string(), RenderView(data, v));
  return data;
}

}  // namespace sfm_pruning::testing
