#include "sfm_pruning/eval/synthetic_layout.hpp"

#include <cmath>

namespace sfm_pruning {

Texture MakeTexture(double width_m, double height_m, double density_per_m2, double relief_m,
                    SceneLayout* layout, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, width_m);
  std::uniform_real_distribution<double> v(0.0, height_m);
  std::uniform_real_distribution<double> w(-relief_m, relief_m);
  const auto count = static_cast<size_t>(std::llround(width_m * height_m * density_per_m2));
  Texture texture;
  texture.uvw.reserve(count);
  texture.appearance.reserve(count);
  for (size_t k = 0; k < count; ++k) {
    const double pu = u(rng);
    const double pv = v(rng);
    texture.uvw.emplace_back(pu, pv, w(rng));
    texture.appearance.push_back(layout->num_appearances++);
  }
  return texture;
}

void PlaceTexture(const Texture& texture, const Eigen::Vector3d& origin, const Eigen::Vector3d& u_axis,
                  const Eigen::Vector3d& v_axis, SceneLayout* layout) {
  const Eigen::Vector3d normal = u_axis.cross(v_axis).normalized();
  for (size_t k = 0; k < texture.uvw.size(); ++k) {
    const Eigen::Vector3d& p = texture.uvw[k];
    SurfacePoint point;
    point.X = origin + p.x() * u_axis + p.y() * v_axis + p.z() * normal;
    point.normal = normal;
    point.appearance = texture.appearance[k];
    layout->points.push_back(point);
  }
}

Pose LookAtPose(const Eigen::Vector3d& center, const Eigen::Vector3d& target) {
  const Eigen::Vector3d forward = (target - center).normalized();
  // Camera axes: x right, y down, z forward. With world z up, right = forward x up.
  const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d down = forward.cross(right);
  Eigen::Matrix3d R;
  R.row(0) = right.transpose();
  R.row(1) = down.transpose();
  R.row(2) = forward.transpose();
  return Pose(R, center);
}

Pose HeadingPitchPose(const Eigen::Vector3d& center, double heading, double pitch) {
  const Eigen::Vector3d forward(std::cos(pitch) * std::cos(heading), std::cos(pitch) * std::sin(heading),
                                std::sin(pitch));
  return LookAtPose(center, center + forward);
}

}  // namespace sfm_pruning
