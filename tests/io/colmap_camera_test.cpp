// COLMAP camera conversion, checked by projecting the same camera-frame points through COLMAP's
// own formulas (written here from the model definitions) and through our CameraIntrinsics.
#include "sfm_pruning/io/colmap_camera.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "sfm_pruning/util/error.hpp"

namespace sfm_pruning {
namespace {

// COLMAP's projection of a camera-frame point, in COLMAP's pixel convention.
Eigen::Vector2d ColmapProject(const ColmapCamera& camera, const Eigen::Vector3d& X) {
  const std::vector<double>& p = camera.params;
  const double x = X.x() / X.z(), y = X.y() / X.z();
  const double r2 = x * x + y * y;
  double fx = p[0], fy = p[0], cx = p[1], cy = p[2], xd = x, yd = y;
  switch (camera.model_id) {
    case 0:  // SIMPLE_PINHOLE f cx cy
      break;
    case 1:  // PINHOLE fx fy cx cy
      fy = p[1], cx = p[2], cy = p[3];
      break;
    case 2:  // SIMPLE_RADIAL f cx cy k
      xd = x * (1 + p[3] * r2), yd = y * (1 + p[3] * r2);
      break;
    case 3: {  // RADIAL f cx cy k1 k2
      const double radial = 1 + p[3] * r2 + p[4] * r2 * r2;
      xd = x * radial, yd = y * radial;
      break;
    }
    case 4:    // OPENCV fx fy cx cy k1 k2 p1 p2
    case 6: {  // FULL_OPENCV fx fy cx cy k1 k2 p1 p2 k3 k4 k5 k6
      fy = p[1], cx = p[2], cy = p[3];
      const double k1 = p[4], k2 = p[5], p1 = p[6], p2 = p[7];
      double radial = 1 + k1 * r2 + k2 * r2 * r2;
      if (camera.model_id == 6) {
        radial = (radial + p[8] * r2 * r2 * r2) / (1 + p[9] * r2 + p[10] * r2 * r2 + p[11] * r2 * r2 * r2);
      }
      xd = x * radial + 2 * p1 * x * y + p2 * (r2 + 2 * x * x);
      yd = y * radial + 2 * p2 * x * y + p1 * (r2 + 2 * y * y);
      break;
    }
    case 5: {  // OPENCV_FISHEYE fx fy cx cy k1 k2 k3 k4
      fy = p[1], cx = p[2], cy = p[3];
      const double r = std::sqrt(r2);
      const double theta = std::atan(r);
      const double t2 = theta * theta;
      const double theta_d =
          theta * (1 + p[4] * t2 + p[5] * t2 * t2 + p[6] * t2 * t2 * t2 + p[7] * t2 * t2 * t2 * t2);
      xd = x * theta_d / r, yd = y * theta_d / r;
      break;
    }
    default:
      ADD_FAILURE() << "model " << camera.model_id << " not in the test";
  }
  return {fx * xd + cx, fy * yd + cy};
}

std::vector<Eigen::Vector3d> TestPoints() {
  std::vector<Eigen::Vector3d> points;
  for (double x : {-0.4, -0.1, 0.05, 0.3}) {
    for (double y : {-0.3, 0.02, 0.25}) points.emplace_back(x * 3.0, y * 3.0, 3.0);
  }
  return points;
}

// Our projection plus the half-pixel shift must equal COLMAP's projection.
void ExpectSameProjection(const ColmapCamera& colmap, const CameraIntrinsics& ours) {
  for (const Eigen::Vector3d& X : TestPoints()) {
    const Eigen::Vector2d expected = ColmapProject(colmap, X);
    const Eigen::Vector2d actual = ToColmapPixel(ours.Project(X));
    EXPECT_NEAR((expected - actual).norm(), 0.0, 1e-9) << ColmapCameraModelName(colmap.model_id);
  }
}

ColmapCamera Camera(int model_id, std::vector<double> params) {
  return {model_id, 640, 480, std::move(params)};
}

struct MappingCase {
  ColmapCamera colmap;
  CameraModel expected_model;
  int expected_back;  // model id ToColmapCamera chooses for the converted intrinsics
};

TEST(ColmapCamera, EveryMappingProjectsLikeColmap) {
  const std::vector<MappingCase> cases = {
      {Camera(0, {800, 320.5, 240.25}), CameraModel::kPinhole, 0},
      {Camera(1, {800, 800, 320.5, 240.25}), CameraModel::kPinhole, 0},
      {Camera(1, {1520.4, 1525.9, 302.32, 246.87}), CameraModel::kPinholeFxFy, 1},
      {Camera(2, {800, 320.5, 240.25, -0.08}), CameraModel::kPinholeRadialK1, 2},
      {Camera(3, {800, 320.5, 240.25, -0.08, 0.02}), CameraModel::kPinholeRadialK3, 3},
      {Camera(4, {800, 800, 320.5, 240.25, -0.08, 0.02, 0.003, -0.002}), CameraModel::kPinholeBrownT2, 4},
      {Camera(6, {800, 800, 320.5, 240.25, -0.08, 0.02, 0.003, -0.002, 0.004, 0, 0, 0}),
       CameraModel::kPinholeBrownT2, 6},
      {Camera(6, {800, 800, 320.5, 240.25, -0.08, 0.02, 0.003, -0.002, 0, 0, 0, 0}),
       CameraModel::kPinholeBrownT2, 4},
      {Camera(5, {700, 700, 320.5, 240.25, 0.01, -0.02, 0.003, -0.001}), CameraModel::kFisheye, 5},
  };
  for (const MappingCase& c : cases) {
    SCOPED_TRACE(ColmapCameraModelName(c.colmap.model_id));
    const CameraIntrinsics ours = FromColmapCamera(c.colmap, "cameras.txt");
    EXPECT_EQ(ours.model(), c.expected_model);
    EXPECT_EQ(ours.width(), 640u);
    EXPECT_EQ(ours.height(), 480u);
    ExpectSameProjection(c.colmap, ours);
    const ColmapCamera back = ToColmapCamera(ours);
    EXPECT_EQ(back.model_id, c.expected_back);
    ExpectSameProjection(back, ours);
  }
}

TEST(ColmapCamera, PrincipalPointShiftsByHalfAPixel) {
  // The top-left pixel centre is (0.5, 0.5) for COLMAP and (0, 0) for us: a ray through the
  // principal point hits cx in each convention, so ours is COLMAP's minus 0.5.
  const CameraIntrinsics ours = FromColmapCamera(Camera(1, {1520.4, 1525.9, 302.32, 246.87}), "db");
  EXPECT_EQ(ours.PrincipalPoint(), Eigen::Vector2d(302.32 - 0.5, 246.87 - 0.5));
  EXPECT_EQ(ours.FocalX(), 1520.4);
  EXPECT_EQ(ours.FocalY(), 1525.9);
  EXPECT_EQ(FromColmapPixel(Eigen::Vector2d(0.5, 0.5)), Eigen::Vector2d(0, 0));
  EXPECT_EQ(ToColmapPixel(Eigen::Vector2d(0, 0)), Eigen::Vector2d(0.5, 0.5));
}

TEST(ColmapCamera, OurModelsMapToColmapAndBack) {
  // Radial K3 with k3 != 0 needs FULL_OPENCV, which reads back as Brown with zero tangential terms.
  const CameraIntrinsics radial_k3(CameraModel::kPinholeRadialK3, 640, 480,
                                   {800, 319.5, 239.5, -0.1, 0.03, -0.004});
  const CameraIntrinsics brown(CameraModel::kPinholeBrownT2, 640, 480,
                               {800, 319.5, 239.5, -0.1, 0.03, -0.004, 0, 0});
  const CameraIntrinsics brown_k3_zero(CameraModel::kPinholeBrownT2, 640, 480,
                                       {800, 319.5, 239.5, -0.1, 0.03, 0, 0.002, 0.001});
  const CameraIntrinsics fisheye(CameraModel::kFisheye, 640, 480,
                                 {600, 319.5, 239.5, 0.01, 0.002, -0.003, 0.0004});
  const std::vector<std::pair<CameraIntrinsics, CameraIntrinsics>> cases = {
      {radial_k3, brown}, {brown, brown}, {brown_k3_zero, brown_k3_zero}, {fisheye, fisheye}};
  for (const auto& [intrinsics, expected] : cases) {
    const ColmapCamera colmap = ToColmapCamera(intrinsics);
    ExpectSameProjection(colmap, intrinsics);
    const CameraIntrinsics back = FromColmapCamera(colmap, "cameras.bin");
    ASSERT_EQ(back.model(), expected.model());
    for (size_t k = 0; k < back.params().size(); ++k)
      EXPECT_DOUBLE_EQ(back.params()[k], expected.params()[k]);
  }
}

void ExpectErrorMentioning(const ColmapCamera& camera, const std::string& text) {
  try {
    FromColmapCamera(camera, "cameras.txt");
    ADD_FAILURE() << "expected an Error mentioning " << text;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cameras.txt"), std::string::npos) << e.what();
  }
}

TEST(ColmapCamera, UnsupportedModelsAreNamed) {
  ExpectErrorMentioning(Camera(7, {800, 800, 320, 240, 0.9}), "FOV");
  ExpectErrorMentioning(Camera(10, std::vector<double>(12, 0.5)), "THIN_PRISM_FISHEYE");
  ExpectErrorMentioning(Camera(4, {800, 810, 320, 240, 0, 0, 0, 0}), "OPENCV with fx != fy");
  ExpectErrorMentioning(Camera(6, {800, 800, 320, 240, 0, 0, 0, 0, 0, 0.1, 0, 0}), "k4");
  ExpectErrorMentioning(Camera(42, {}), "UNKNOWN_MODEL_42");
  ExpectErrorMentioning(Camera(1, {800, 800, 320}), "takes 4 parameters");
  EXPECT_THROW(ToColmapCamera(CameraIntrinsics(CameraModel::kSpherical, 2000, 1000, {})), Error);
}

}  // namespace
}  // namespace sfm_pruning
