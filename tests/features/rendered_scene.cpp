#include "features/rendered_scene.hpp"

#include <cmath>
#include <limits>

#include <Eigen/Geometry>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace sfm_pruning::testing {
namespace {

double LatticeValue(int64_t x, int64_t y, uint64_t seed) {
  uint64_t h = seed * 0x9e3779b97f4a7c15ULL ^ static_cast<uint64_t>(x) * 0xbf58476d1ce4e5b9ULL ^
               static_cast<uint64_t>(y) * 0x94d049bb133111ebULL;
  h ^= h >> 31;
  h *= 0xd6e8feb86659fd93ULL;
  h ^= h >> 32;
  return static_cast<double>(h & 0xffffff) / 0xffffff;
}

// Smooth value noise: bicubic-faded interpolation of a hashed lattice of cell size 1.
double ValueNoise(double u, double v, uint64_t seed) {
  const double fu = std::floor(u);
  const double fv = std::floor(v);
  const auto x = static_cast<int64_t>(fu);
  const auto y = static_cast<int64_t>(fv);
  const double a = u - fu;
  const double b = v - fv;
  const double sa = a * a * (3 - 2 * a);
  const double sb = b * b * (3 - 2 * b);
  const double top = LatticeValue(x, y, seed) * (1 - sa) + LatticeValue(x + 1, y, seed) * sa;
  const double bottom = LatticeValue(x, y + 1, seed) * (1 - sa) + LatticeValue(x + 1, y + 1, seed) * sa;
  return top * (1 - sb) + bottom * sb;
}

// Texture in metres on a surface: octaves of 0.4, 0.16 and 0.064 m cells.
double Texture(double u, double v, uint64_t seed) {
  return 0.5 * ValueNoise(u / 0.4, v / 0.4, seed) + 0.3 * ValueNoise(u / 0.16, v / 0.16, seed + 1) +
         0.2 * ValueNoise(u / 0.064, v / 0.064, seed + 2);
}

}  // namespace

std::vector<RenderedCamera> RoomCameras(int num_views, int width, int height, double focal) {
  std::vector<RenderedCamera> cameras;
  for (int k = 0; k < num_views; ++k) {
    const double yaw = (4.0 - 2.0 * k) * M_PI / 180.0;  // turn slightly, so the rotations differ
    const Eigen::Matrix3d R = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitY()).toRotationMatrix().transpose();
    cameras.push_back({Pose(R, Eigen::Vector3d(0.35 * k - 0.5, 0.1 * (k % 2), 0.0)), focal, width, height});
  }
  return cameras;
}

cv::Mat RenderRoom(const RenderedCamera& camera, uint64_t seed) {
  cv::Mat image(camera.height, camera.width, CV_8UC1);
  const Eigen::Matrix3d Rt = camera.pose.rotation.transpose();
  const Eigen::Vector3d& c = camera.pose.center;
  for (int y = 0; y < camera.height; ++y) {
    for (int x = 0; x < camera.width; ++x) {
      const Eigen::Vector3d ray =
          Rt * Eigen::Vector3d((x - 0.5 * (camera.width - 1)) / camera.focal, (y - 0.5 * (camera.height - 1)) / camera.focal, 1.0);
      double best = std::numeric_limits<double>::infinity();
      double value = 0.5;
      const auto hit = [&](double t, double u, double v, uint64_t surface) {
        if (t > 0 && t < best) {
          best = t;
          value = Texture(u, v, seed * 16 + surface * 4);
        }
      };
      if (ray.z() > 1e-9) {  // back wall z = 6
        const double t = (6.0 - c.z()) / ray.z();
        hit(t, c.x() + t * ray.x(), c.y() + t * ray.y(), 0);
      }
      if (ray.x() < -1e-9) {  // left wall x = -3
        const double t = (-3.0 - c.x()) / ray.x();
        hit(t, c.z() + t * ray.z(), c.y() + t * ray.y(), 1);
      }
      if (ray.y() > 1e-9) {  // floor y = 1.5 (y points down)
        const double t = (1.5 - c.y()) / ray.y();
        hit(t, c.x() + t * ray.x(), c.z() + t * ray.z(), 2);
      }
      image.at<uint8_t>(y, x) = static_cast<uint8_t>(std::lround(std::clamp(value, 0.0, 1.0) * 255.0));
    }
  }
  return image;
}

std::vector<std::string> WriteRoomImages(const std::filesystem::path& dir, int num_views, const char* extension) {
  std::filesystem::create_directories(dir);
  std::vector<std::string> names;
  const std::vector<RenderedCamera> cameras = RoomCameras(num_views);
  for (size_t k = 0; k < cameras.size(); ++k) {
    names.push_back("view_" + std::to_string(k) + extension);
    cv::imwrite((dir / names.back()).string(), RenderRoom(cameras[k]));
  }
  return names;
}

}  // namespace sfm_pruning::testing
