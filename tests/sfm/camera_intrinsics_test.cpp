#include "sfm_pruning/sfm/camera_intrinsics.hpp"

#include <gtest/gtest.h>

#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace {

struct ModelCase {
  const char* label;
  CameraIntrinsics camera;
};

std::vector<ModelCase> AllModels() {
  return {
      {"pinhole", CameraIntrinsics(CameraModel::kPinhole, 3072, 2048, {2760.0, 1520.5, 1010.25})},
      {"radial_k1", CameraIntrinsics(CameraModel::kPinholeRadialK1, 3072, 2048, {2760.0, 1536.0, 1024.0, -0.12})},
      {"radial_k3", CameraIntrinsics(CameraModel::kPinholeRadialK3, 3072, 2048,
                                     {2760.0, 1536.0, 1024.0, -0.15, 0.08, -0.01})},
      {"brown_t2", CameraIntrinsics(CameraModel::kPinholeBrownT2, 3072, 2048,
                                    {2760.0, 1536.0, 1024.0, -0.15, 0.08, -0.01, 0.001, -0.0007})},
      {"fisheye", CameraIntrinsics(CameraModel::kFisheye, 1280, 1024, {600.0, 640.0, 512.0, 0.02, -0.01, 0.003, -0.0005})},
      {"fx_fy", CameraIntrinsics(CameraModel::kPinholeFxFy, 640, 480, {1520.4, 1525.9, 302.32, 246.87})},
      {"spherical", CameraIntrinsics(CameraModel::kSpherical, 4000, 2000, {})},
  };
}

// Unproject(Project(X)) must give X's direction, and Project(Unproject(u)) must give u back,
// over a grid covering the image (corners included; the fisheye corner is 78 degrees off axis).
TEST(CameraIntrinsics, ProjectAndUnprojectAreInverse) {
  for (const ModelCase& c : AllModels()) {
    SCOPED_TRACE(c.label);
    const CameraIntrinsics& cam = c.camera;
    for (double fu : {0.0, 0.1, 0.5, 0.77, 1.0}) {
      for (double fv : {0.0, 0.3, 0.5, 1.0}) {
        const Eigen::Vector2d pixel(fu * (cam.width() - 1), fv * (cam.height() - 1));
        const Eigen::Vector3d bearing = cam.Unproject(pixel);
        EXPECT_NEAR(bearing.norm(), 1.0, 1e-12);
        const Eigen::Vector2d back = cam.Project(3.7 * bearing);
        EXPECT_NEAR((back - pixel).norm(), 0.0, 1e-6) << "pixel " << pixel.transpose();
      }
    }
  }
}

TEST(CameraIntrinsics, PinholeProjectionMatchesHandComputation) {
  const CameraIntrinsics cam = CameraIntrinsics::Pinhole(3072, 2048, 2760.0, 1536.0, 1024.0);
  // X = (0.5, 0.1, 5) -> normalized (0.1, 0.02) -> pixel (1536 + 276, 1024 + 55.2).
  const Eigen::Vector2d pixel = cam.Project({0.5, 0.1, 5.0});
  EXPECT_NEAR(pixel.x(), 1812.0, 1e-9);
  EXPECT_NEAR(pixel.y(), 1079.2, 1e-9);
}

TEST(CameraIntrinsics, RadialK1DistortionMatchesHandComputation) {
  const CameraIntrinsics cam(CameraModel::kPinholeRadialK1, 100, 100, {100.0, 50.0, 50.0, 0.1});
  // normalized (0.2, 0.1): r^2 = 0.05, factor 1.005 -> (0.201, 0.1005) -> pixel (70.1, 60.05).
  const Eigen::Vector2d pixel = cam.NormalizedToPixel({0.2, 0.1});
  EXPECT_NEAR(pixel.x(), 70.1, 1e-12);
  EXPECT_NEAR(pixel.y(), 60.05, 1e-12);
}

TEST(CameraIntrinsics, BrownTangentialTermsFollowOpenMVGOrder) {
  // Only t2 set: x moves by t2 (r^2 + 2x^2), y by 2 t2 x y.
  const CameraIntrinsics cam(CameraModel::kPinholeBrownT2, 100, 100, {1.0, 0.0, 0.0, 0, 0, 0, 0.0, 0.01});
  const Eigen::Vector2d d = cam.NormalizedToPixel({0.2, 0.1});
  EXPECT_NEAR(d.x(), 0.2 + 0.01 * (0.05 + 0.08), 1e-15);
  EXPECT_NEAR(d.y(), 0.1 + 2 * 0.01 * 0.2 * 0.1, 1e-15);
}

TEST(CameraIntrinsics, FisheyeIsEquidistant) {
  const CameraIntrinsics cam(CameraModel::kFisheye, 1000, 1000, {300.0, 500.0, 500.0, 0, 0, 0, 0});
  // A ray 60 degrees off axis lands 300 * pi/3 pixels from the centre.
  const double angle = M_PI / 3;
  const Eigen::Vector2d pixel = cam.Project({std::sin(angle), 0.0, std::cos(angle)});
  EXPECT_NEAR(pixel.x() - 500.0, 300.0 * angle, 1e-9);
  EXPECT_NEAR(pixel.y(), 500.0, 1e-12);
}

TEST(CameraIntrinsics, SphericalMapsAxesToKnownPixels) {
  const CameraIntrinsics cam(CameraModel::kSpherical, 4000, 2000, {});
  EXPECT_TRUE(cam.Project({0, 0, 1}).isApprox(Eigen::Vector2d(2000, 1000)));
  // Looking right (+x) is a quarter turn: 4000 / 4 pixels right of the centre.
  EXPECT_NEAR(cam.Project({1, 0, 0}).x(), 3000.0, 1e-9);
  // Up (-y) is latitude +90 deg, a quarter turn above the centre row.
  EXPECT_NEAR(cam.Project({0, -1, 1e-12}).y(), 0.0, 1e-6);
}

TEST(CameraIntrinsics, AccessorsAndSetters) {
  CameraIntrinsics cam(CameraModel::kPinholeRadialK3, 640, 480, {500.0, 320.0, 240.0, 0.0, 0.0, 0.0});
  EXPECT_FALSE(cam.HasDistortion());
  cam.mutable_params()[4] = 0.01;
  EXPECT_TRUE(cam.HasDistortion());
  cam.SetFocalLength(600.0);
  cam.SetPrincipalPoint({321.0, 239.0});
  EXPECT_EQ(cam.FocalLength(), 600.0);
  EXPECT_EQ(cam.PrincipalPoint(), Eigen::Vector2d(321.0, 239.0));
  EXPECT_EQ(cam.DistortionParams(), (std::vector<double>{0.0, 0.01, 0.0}));
}

TEST(CameraIntrinsics, WrongParameterCountIsAnError) {
  EXPECT_THROW(CameraIntrinsics(CameraModel::kPinholeRadialK3, 10, 10, {1.0, 2.0}), Error);
}

TEST(CameraModel, NamesRoundTrip) {
  for (const ModelCase& c : AllModels()) {
    CameraModel parsed;
    ASSERT_TRUE(CameraModelFromName(CameraModelName(c.camera.model()), &parsed));
    EXPECT_EQ(parsed, c.camera.model());
  }
  CameraModel unused;
  EXPECT_FALSE(CameraModelFromName("no_such_model", &unused));
}

}  // namespace
}  // namespace sfm_pruning
