// Undistortion to a pinhole camera for every camera model: the chosen camera, the pixel maps and
// resampled images against a rendered ground truth.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "export/rendered_scene.hpp"
#include "sfm_pruning/export/undistortion.hpp"

namespace sfm_pruning {
namespace {

struct NamedCamera {
  std::string name;
  CameraIntrinsics camera;
};

// One camera of every pinhole-family model, 320 x 240, with realistic (visible) distortion.
std::vector<NamedCamera> Cameras() {
  return {
      {"pinhole", CameraIntrinsics::Pinhole(320, 240, 300.0, 161.0, 118.5)},
      {"pinhole_fx_fy", CameraIntrinsics(CameraModel::kPinholeFxFy, 320, 240, {300.0, 290.0, 161.0, 118.5})},
      {"radial_k1_barrel",
       CameraIntrinsics(CameraModel::kPinholeRadialK1, 320, 240, {300.0, 161.0, 118.5, -0.25})},
      {"radial_k1_pincushion",
       CameraIntrinsics(CameraModel::kPinholeRadialK1, 320, 240, {300.0, 158.0, 121.5, 0.2})},
      {"radial_k3",
       CameraIntrinsics(CameraModel::kPinholeRadialK3, 320, 240, {300.0, 161.0, 118.5, -0.3, 0.12, -0.02})},
      {"brown_t2", CameraIntrinsics(CameraModel::kPinholeBrownT2, 320, 240,
                                    {300.0, 161.0, 118.5, -0.2, 0.05, 0.0, 0.004, -0.003})},
      {"fisheye",
       CameraIntrinsics(CameraModel::kFisheye, 320, 240, {160.0, 160.5, 119.0, 0.02, -0.01, 0.003, 0.0})},
  };
}

bool InsideCentres(const Eigen::Vector2d& p, const CameraIntrinsics& camera, double tolerance) {
  return p.x() >= -tolerance && p.y() >= -tolerance && p.x() <= camera.width() - 1 + tolerance &&
         p.y() <= camera.height() - 1 + tolerance;
}

TEST(Undistortion, PinholeCamerasAreKeptAsTheyAre) {
  for (const NamedCamera& named : Cameras()) {
    if (named.camera.HasDistortion()) continue;
    SCOPED_TRACE(named.name);
    const CameraIntrinsics undistorted = UndistortedIntrinsics(named.camera);
    EXPECT_EQ(undistorted.model(), CameraModel::kPinholeFxFy);
    EXPECT_TRUE(SameProjection(named.camera, undistorted));
  }
}

TEST(Undistortion, CropModeHasNoBlackBordersAndCropsLittle) {
  for (const NamedCamera& named : Cameras()) {
    if (!named.camera.HasDistortion()) continue;
    SCOPED_TRACE(named.name);
    const CameraIntrinsics& original = named.camera;
    const CameraIntrinsics undistorted = UndistortedIntrinsics(original);
    EXPECT_EQ(undistorted.model(), CameraModel::kPinholeFxFy);
    EXPECT_EQ(undistorted.width(), original.width());
    EXPECT_NEAR(undistorted.FocalX() / undistorted.FocalY(), original.FocalX() / original.FocalY(), 1e-12);
    const UndistortionMaps maps = ComputeUndistortionMaps(original, undistorted);
    ASSERT_EQ(maps.map_x.cols, 320);
    ASSERT_EQ(maps.map_x.rows, 240);
    // Every output pixel samples inside the source's pixel centres (no black), and the view is
    // tight: the sources reach within 1.5 pixels of the frame on both sides of at least one axis.
    double min_x = 1e9, max_x = -1e9, min_y = 1e9, max_y = -1e9;
    for (int v = 0; v < 240; ++v) {
      for (int u = 0; u < 320; ++u) {
        const Eigen::Vector2d source(maps.map_x.at<float>(v, u), maps.map_y.at<float>(v, u));
        ASSERT_TRUE(InsideCentres(source, original, 1e-3)) << u << "," << v << " -> " << source.transpose();
        min_x = std::min(min_x, source.x());
        max_x = std::max(max_x, source.x());
        min_y = std::min(min_y, source.y());
        max_y = std::max(max_y, source.y());
      }
    }
    const bool tight_x = min_x < 1.5 && max_x > 317.5;
    const bool tight_y = min_y < 1.5 && max_y > 237.5;
    EXPECT_TRUE(tight_x || tight_y) << min_x << " " << max_x << " " << min_y << " " << max_y;
  }
}

TEST(Undistortion, KeepAllPixelsModeLosesNoSourcePixel) {
  UndistortOptions options;
  options.fit = UndistortFit::kKeepAllPixels;
  for (const NamedCamera& named : Cameras()) {
    if (!named.camera.HasDistortion()) continue;
    SCOPED_TRACE(named.name);
    const CameraIntrinsics& original = named.camera;
    const CameraIntrinsics undistorted = UndistortedIntrinsics(original, options);
    // Every pixel centre on the source's border lands inside the output, and some reach its edge.
    double outermost = 0;
    for (int k = 0; k <= 100; ++k) {
      const double u = 319.0 * k / 100, v = 239.0 * k / 100;
      for (const Eigen::Vector2d& p :
           {Eigen::Vector2d(u, 0), Eigen::Vector2d(u, 239), Eigen::Vector2d(0, v), Eigen::Vector2d(319, v)}) {
        const Eigen::Vector2d q = UndistortedPixel(original, undistorted, p);
        EXPECT_TRUE(InsideCentres(q, undistorted, 1e-6)) << p.transpose() << " -> " << q.transpose();
        outermost = std::max({outermost, std::abs(q.x() - 159.5) / 159.5, std::abs(q.y() - 119.5) / 119.5});
      }
    }
    EXPECT_GT(outermost, 0.99);
  }
}

TEST(Undistortion, PointsMoveAlongTheirRays) {
  for (const NamedCamera& named : Cameras()) {
    SCOPED_TRACE(named.name);
    const CameraIntrinsics& original = named.camera;
    const CameraIntrinsics undistorted = UndistortedIntrinsics(original);
    for (double x = -0.4; x <= 0.4; x += 0.1) {
      for (double y = -0.3; y <= 0.3; y += 0.1) {
        const Eigen::Vector3d X(x, y, 1.0);
        const Eigen::Vector2d distorted = original.Project(X);
        EXPECT_LT((UndistortedPixel(original, undistorted, distorted) - undistorted.Project(X)).norm(), 1e-6);
        EXPECT_LT((DistortedPixel(original, undistorted, undistorted.Project(X)) - distorted).norm(), 1e-6);
      }
    }
  }
}

TEST(Undistortion, ResampledImagesMatchARenderedPinholeView) {
  for (const NamedCamera& named : Cameras()) {
    SCOPED_TRACE(named.name);
    SfmData scene;
    scene.intrinsics[0] = named.camera;
    View view;
    view.id_view = view.id_pose = view.id_intrinsic = 0;
    scene.views[0] = view;
    scene.poses[0] = Pose(Eigen::AngleAxisd(0.3, Eigen::Vector3d(0.2, 1, 0).normalized()).toRotationMatrix(),
                          Eigen::Vector3d::Zero());
    const cv::Mat image = testing::RenderView(scene, 0);
    const CameraIntrinsics undistorted = UndistortedIntrinsics(named.camera);
    const cv::Mat resampled = UndistortImage(image, ComputeUndistortionMaps(named.camera, undistorted));
    ASSERT_EQ(resampled.size(), image.size());
    ASSERT_EQ(resampled.type(), CV_8UC3);
    // Compare with the scene rendered directly through the pinhole camera.
    SfmData pinhole = scene;
    pinhole.intrinsics[0] = undistorted;
    const cv::Mat expected = testing::RenderView(pinhole, 0);
    double sum = 0, worst = 0;
    for (int v = 0; v < image.rows; ++v) {
      for (int u = 0; u < image.cols; ++u) {
        for (int c = 0; c < 3; ++c) {
          const double error = std::abs(resampled.at<cv::Vec3b>(v, u)[c] - expected.at<cv::Vec3b>(v, u)[c]);
          sum += error;
          worst = std::max(worst, error);
        }
      }
    }
    // Bilinear resampling of a smooth image plus 8-bit rounding.
    EXPECT_LT(sum / (3.0 * image.total()), 1.0);
    EXPECT_LE(worst, 12.0);
  }
}

TEST(Undistortion, SphericalCamerasBecomeSixCubeFaces) {
  const CameraIntrinsics spherical(CameraModel::kSpherical, 400, 200, {});
  const CameraIntrinsics face = UndistortedIntrinsics(spherical);
  EXPECT_EQ(face, CameraIntrinsics(CameraModel::kPinholeFxFy, 100, 100, {50.0, 50.0, 49.5, 49.5}));
  // 90 degrees across: the outer pixel edges look 45 degrees off axis.
  EXPECT_NEAR(face.Unproject({-0.5, 49.5}).x(), -std::sqrt(0.5), 1e-12);
  for (int k = 0; k < kNumCubeFaces; ++k) {
    SCOPED_TRACE(CubeFaceNames()[k]);
    const Eigen::Matrix3d& R = CubeFaceRotations()[k];
    EXPECT_LT((R * R.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-15);
    EXPECT_NEAR(R.determinant(), 1.0, 1e-15);
    // The face's axis belongs to it, and a direction 44 degrees off its axis still does.
    const Eigen::Vector3d axis = R.row(2).transpose();
    EXPECT_EQ(CubeFaceOf(axis), k);
    EXPECT_EQ(CubeFaceOf(axis + std::tan(DegToRad(44.0)) * R.row(0).transpose()), k);
    // The spherical image and the face see the same colour along a ray of the face.
    const Eigen::Vector3d ray = R.transpose() * Eigen::Vector3d(0.3, -0.2, 1.0);
    const UndistortionMaps maps = ComputeUndistortionMaps(spherical, face, R);
    const Eigen::Vector2d pixel = face.Project(R * ray);
    const int u = static_cast<int>(std::lround(pixel.x())), v = static_cast<int>(std::lround(pixel.y()));
    const Eigen::Vector2d expected = spherical.Project(R.transpose() * face.Unproject(Eigen::Vector2d(u, v)));
    EXPECT_NEAR(maps.map_x.at<float>(v, u), expected.x(), 1e-3);
    EXPECT_NEAR(maps.map_y.at<float>(v, u), expected.y(), 1e-3);
  }
  // "up" looks along the camera's -y (y points down in the image).
  EXPECT_EQ(CubeFaceNames()[CubeFaceOf(Eigen::Vector3d(0, -1, 0))], "up");
  EXPECT_EQ(CubeFaceNames()[CubeFaceOf(Eigen::Vector3d(1, 0, 0))], "right");
}

}  // namespace
}  // namespace sfm_pruning
