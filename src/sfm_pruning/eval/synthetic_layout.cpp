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

void PlaceTextureOnCylinder(const Texture& texture, const Eigen::Vector3d& base, double radius_m,
                            double start_angle, bool outward, SceneLayout* layout) {
  for (size_t k = 0; k < texture.uvw.size(); ++k) {
    const Eigen::Vector3d& p = texture.uvw[k];
    // Seen from inside, u runs clockwise so that the print is not mirrored for the viewer.
    const double angle = start_angle + (outward ? 1.0 : -1.0) * p.x() / radius_m;
    const Eigen::Vector3d radial(std::cos(angle), std::sin(angle), 0.0);
    const double r = radius_m + (outward ? p.z() : -p.z());
    SurfacePoint point;
    point.X = base + r * radial + p.y() * Eigen::Vector3d::UnitZ();
    point.normal = outward ? radial : Eigen::Vector3d(-radial);
    point.appearance = texture.appearance[k];
    layout->points.push_back(point);
  }
}

std::array<BoxSide, 4> BoxSideFaces(const Eigen::Vector3d& center, const Eigen::Vector3d& length_axis,
                                    double length_m, double depth_m) {
  const Eigen::Vector3d& x = length_axis;
  const Eigen::Vector3d y = Eigen::Vector3d::UnitZ().cross(x);
  const double a = 0.5 * length_m, b = 0.5 * depth_m;
  return {{{center - a * x - b * y, x, length_m},
           {center + a * x - b * y, y, depth_m},
           {center + a * x + b * y, -x, length_m},
           {center - a * x + b * y, -y, depth_m}}};
}

Eigen::Vector3d RotateAboutZ(const Eigen::Vector3d& v, double angle) {
  return Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()) * v;
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
