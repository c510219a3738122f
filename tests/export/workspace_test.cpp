// Point colours from images, the COLMAP undistorted workspace and the OpenMVS workspace, written
// from a small rendered scene; and the colour order of the real OpenMVS sample.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include <opencv2/imgcodecs.hpp>

#include "export/rendered_scene.hpp"
#include "sfm_pruning/export/dense_workspaces.hpp"
#include "sfm_pruning/export/image_files.hpp"
#include "sfm_pruning/export/point_colors.hpp"
#include "sfm_pruning/io/colmap_model.hpp"
#include "sfm_pruning/io/openmvs_conversion.hpp"
#include "sfm_pruning/io/openmvs_scene.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning {
namespace {
namespace fs = std::filesystem;

CameraIntrinsics DistortedCamera() {
  return CameraIntrinsics(CameraModel::kPinholeRadialK3, 160, 120, {150.0, 81.0, 58.5, -0.25, 0.08, 0.0});
}

std::string ErrorOf(const std::function<void()>& call) {
  try {
    call();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(PointColors, AreTheMeanOverTheObservingImages) {
  const fs::path dir = testing::ScratchDir("point_colors");
  SfmData data = testing::MakeRenderedScene(DistortedCamera(), dir / "images");
  // Repaint every image in one colour so that the expected mean is exact.
  const cv::Vec3b colors[3] = {{10, 100, 250}, {20, 101, 200}, {31, 103, 0}};  // BGR
  for (IndexT v = 0; v < 3; ++v) {
    cv::imwrite((dir / "images" / data.views[v].filename).string(),
                cv::Mat(120, 160, CV_8UC3, cv::Scalar(colors[v])));
  }
  // Landmark 0 is seen by views 0 and 2 only; landmark 1 has one observation outside its image.
  data.structure[0].observations.erase(1);
  data.structure[1].observations[2].x = {-3.0, 40.0};
  ColorLandmarksFromImages(&data, dir / "images", 2);
  EXPECT_EQ(data.structure[0].color,
            (std::array<uint8_t, 3>{125, 102, 21}));  // (250+0)/2, (100+103)/2 = 101.5
  EXPECT_EQ(data.structure[1].color, (std::array<uint8_t, 3>{225, 101, 15}));
  EXPECT_EQ(data.structure[5].color, (std::array<uint8_t, 3>{150, 101, 20}));  // 450/3, 304/3, 61/3
}

TEST(PointColors, MissingOrBrokenImagesGiveOneLineErrors) {
  const fs::path dir = testing::ScratchDir("point_colors_errors");
  SfmData data = testing::MakeRenderedScene(DistortedCamera(), dir / "images");
  fs::remove(dir / "images" / "view1.png");
  std::string message = ErrorOf([&] { ColorLandmarksFromImages(&data, dir / "images", 2); });
  EXPECT_EQ(message, (dir / "images" / "view1.png").string() + ": no such image file");
  std::ofstream(dir / "images" / "view1.png") << "not a png";
  message = ErrorOf([&] { ColorLandmarksFromImages(&data, dir / "images", 2); });
  EXPECT_EQ(message, (dir / "images" / "view1.png").string() + ": cannot be decoded as an image");
}

// Mean absolute difference between an image and the scene rendered through `camera` with the
// pose of `view_id`, over the pixels more than `margin` from the border.
double MeanDifferenceToRendering(const cv::Mat& image, const SfmData& data, IndexT view_id,
                                 const CameraIntrinsics& camera, int margin) {
  SfmData pinhole = data;
  pinhole.intrinsics[data.views.at(view_id).id_intrinsic] = camera;
  const cv::Mat expected = testing::RenderView(pinhole, view_id);
  double sum = 0;
  int count = 0;
  for (int v = margin; v < image.rows - margin; ++v) {
    for (int u = margin; u < image.cols - margin; ++u) {
      for (int c = 0; c < 3; ++c)
        sum += std::abs(image.at<cv::Vec3b>(v, u)[c] - expected.at<cv::Vec3b>(v, u)[c]);
      count += 3;
    }
  }
  return sum / count;
}

TEST(ColmapUndistortedWorkspace, HoldsPinholeCamerasConsistentImagesAndStereoConfigs) {
  const fs::path dir = testing::ScratchDir("colmap_workspace");
  const SfmData data = testing::MakeRenderedScene(DistortedCamera(), dir / "images");
  DenseWorkspaceOptions options;
  options.images.num_threads = 2;
  WriteColmapUndistortedWorkspace(data, dir / "images", dir / "workspace", options);
  const fs::path workspace = dir / "workspace";
  for (const char* file : {"sparse/cameras.bin", "sparse/images.bin", "sparse/points3D.bin",
                           "stereo/patch-match.cfg", "stereo/fusion.cfg", "run-colmap-geometric.sh"}) {
    EXPECT_TRUE(fs::is_regular_file(workspace / file)) << file;
  }
  // Splatting and NeRF tools open images/ and sparse/0/*.bin: the same model, also there.
  for (const char* name : {"cameras.bin", "images.bin", "points3D.bin"}) {
    EXPECT_EQ(ReadFileToString(workspace / "sparse" / "0" / name), ReadFileToString(workspace / "sparse" / name))
        << name;
  }
  EXPECT_EQ(ReadColmapModel(workspace / "sparse" / "0").structure.size(), data.structure.size());
  for (const char* folder : {"stereo/depth_maps", "stereo/normal_maps", "stereo/consistency_graphs"}) {
    EXPECT_TRUE(fs::is_directory(workspace / folder)) << folder;
  }
  EXPECT_EQ(ReadFileToString(workspace / "stereo/patch-match.cfg", false),
            "view0.png\n__auto__, 20\nview1.png\n__auto__, 20\nview2.png\n__auto__, 20\n");
  EXPECT_EQ(ReadFileToString(workspace / "stereo/fusion.cfg", false), "view0.png\nview1.png\nview2.png\n");

  // cameras.bin: uint64 count, then camera_id int32, model_id int32 (1 = PINHOLE), ...
  const std::string cameras = ReadFileToString(workspace / "sparse/cameras.bin");
  ASSERT_GE(cameras.size(), 16u);
  int32_t model_id = -1;
  std::memcpy(&model_id, cameras.data() + 12, 4);
  EXPECT_EQ(model_id, 1);
  const SfmData model = ReadColmapModel(workspace / "sparse");
  ASSERT_EQ(model.intrinsics.size(), 1u);
  const CameraIntrinsics& camera = model.intrinsics.begin()->second;
  EXPECT_FALSE(camera.HasDistortion());
  EXPECT_EQ(camera.width(), 160u);
  ASSERT_EQ(model.structure.size(), data.structure.size());
  // The observations moved with the images: they are the pinhole projections of the points.
  double worst = 0;
  for (const auto& [id, landmark] : model.structure) {
    for (const auto& [view_id, observation] : landmark.observations) {
      const Eigen::Vector2d projected =
          camera.Project(model.PoseOf(model.views.at(view_id)).ToCamera(landmark.X));
      worst = std::max(worst, (projected - observation.x).norm());
    }
  }
  EXPECT_LT(worst, 1e-6);
  for (const auto& [view_id, view] : model.views) {
    SCOPED_TRACE(view.filename);
    const cv::Mat image = ReadColorImage(workspace / "images" / view.filename);
    ASSERT_EQ(image.cols, 160);
    ASSERT_EQ(image.rows, 120);
    EXPECT_LT(MeanDifferenceToRendering(image, data, view_id, camera, 0), 1.5);
  }
}

TEST(ColmapUndistortedWorkspace, KeepAllPixelsLeavesBlackCorners) {
  const fs::path dir = testing::ScratchDir("colmap_workspace_keep_all");
  const SfmData data = testing::MakeRenderedScene(DistortedCamera(), dir / "images");
  DenseWorkspaceOptions options;
  options.undistort.fit = UndistortFit::kKeepAllPixels;
  WriteColmapUndistortedWorkspace(data, dir / "images", dir / "workspace", options);
  const cv::Mat image = ReadColorImage(dir / "workspace" / "images" / "view1.png");
  // Barrel distortion: undistorting pushes the source's corners out further than its edge
  // midpoints, so the output's corners are filled and the middles of its edges are black.
  EXPECT_EQ(image.at<cv::Vec3b>(60, 0), cv::Vec3b(0, 0, 0));
  EXPECT_EQ(image.at<cv::Vec3b>(0, 80), cv::Vec3b(0, 0, 0));
  EXPECT_NE(image.at<cv::Vec3b>(1, 1), cv::Vec3b(0, 0, 0));
  EXPECT_NE(image.at<cv::Vec3b>(60, 80), cv::Vec3b(0, 0, 0));
}

TEST(ColmapUndistortedWorkspace, ImagesOfTheWrongSizeAreReported) {
  const fs::path dir = testing::ScratchDir("colmap_workspace_size");
  const SfmData data = testing::MakeRenderedScene(DistortedCamera(), dir / "images");
  cv::imwrite((dir / "images" / "view2.png").string(), cv::Mat(100, 160, CV_8UC3, cv::Scalar::all(9)));
  const std::string message =
      ErrorOf([&] { WriteColmapUndistortedWorkspace(data, dir / "images", dir / "workspace"); });
  EXPECT_EQ(message,
            (dir / "images" / "view2.png").string() + ": image is 160x100 but its camera is 160x120");
  EXPECT_FALSE(fs::exists(dir / "workspace"));  // nothing half-written
}

TEST(OpenMvsWorkspace, SceneNamesTheUndistortedImagesBesideIt) {
  const fs::path dir = testing::ScratchDir("openmvs_workspace");
  SfmData data = testing::MakeRenderedScene(DistortedCamera(), dir / "images");
  data.structure[3].color = {1, 2, 3};
  WriteOpenMvsWorkspace(data, dir / "images", dir / "mvs");
  const OpenMvsScene scene = ReadOpenMvsScene(dir / "mvs" / "scene.mvs");
  EXPECT_EQ(scene.version, kOpenMvsExportVersion);
  ASSERT_EQ(scene.images.size(), 3u);
  ASSERT_EQ(scene.vertices.size(), 40u);
  EXPECT_EQ(scene.vertex_colors[3], (OpenMvsScene::ColorBgr{3, 2, 1}));
  const SfmData read = SfmDataFromOpenMvsScene(scene, "scene.mvs");
  const CameraIntrinsics& camera = read.intrinsics.begin()->second;
  EXPECT_FALSE(camera.HasDistortion());
  for (const OpenMvsScene::Image& image : scene.images) {
    SCOPED_TRACE(image.name);
    ASSERT_TRUE(fs::is_regular_file(dir / "mvs" / image.name));
    const cv::Mat pixels = ReadColorImage(dir / "mvs" / image.name);
    EXPECT_LT(MeanDifferenceToRendering(pixels, data, image.id, camera, 0), 1.5);
  }
}

// A spherical view becomes six cube faces: pinhole views with their own poses, the observations
// in the face their ray falls in, images showing what a pinhole camera there would see.
TEST(ColmapUndistortedWorkspace, SphericalViewsBecomeCubeFaces) {
  const fs::path dir = testing::ScratchDir("colmap_workspace_spherical");
  SfmData data;
  data.root_path = (dir / "images").string();
  data.intrinsics[4] = CameraIntrinsics(CameraModel::kSpherical, 256, 128, {});
  View view;
  view.id_view = 2;
  view.id_pose = 3;
  view.id_intrinsic = 4;
  view.filename = "pano.png";
  view.width = 256;
  view.height = 128;
  data.views[2] = view;
  data.poses[3] = Pose(Eigen::AngleAxisd(0.4, Eigen::Vector3d(0.1, 1, 0.2).normalized()).toRotationMatrix(),
                       Eigen::Vector3d(0.5, -0.2, 1.0));
  // Points all around the camera: 26 directions of a cube's faces, edges and corners.
  IndexT k = 0;
  for (int x = -1; x <= 1; ++x) {
    for (int y = -1; y <= 1; ++y) {
      for (int z = -1; z <= 1; ++z) {
        if (x == 0 && y == 0 && z == 0) continue;
        Landmark landmark;
        landmark.X = data.poses[3].ToWorld(3.0 * Eigen::Vector3d(x + 0.1, y - 0.05, z + 0.02).normalized());
        landmark.observations[2] = {data.intrinsics[4].Project(data.poses[3].ToCamera(landmark.X)), k};
        data.structure[k++] = landmark;
      }
    }
  }
  fs::create_directories(dir / "images");
  cv::imwrite((dir / "images" / "pano.png").string(), testing::RenderView(data, 2));

  // An unposed panorama seeing the first point is dropped with its observation.
  SfmData with_unposed = data;
  View unposed = view;
  unposed.id_view = 0;
  unposed.id_pose = kUndefinedIndex;
  with_unposed.views[0] = unposed;
  with_unposed.structure[0].observations[0] = {Eigen::Vector2d(10, 10), 0};
  const UndistortedModel dropped = UndistortModel(with_unposed);
  EXPECT_EQ(dropped.data.views.count(0), 0u);
  EXPECT_EQ(dropped.data.structure.at(0).observations.size(), 1u);
  ValidateSfmData(dropped.data, "undistorted");

  const UndistortedModel undistorted = UndistortModel(data);
  ASSERT_EQ(undistorted.data.views.size(), 6u);
  EXPECT_EQ(undistorted.data.views.begin()->first, 3u);  // after the largest original view id
  EXPECT_EQ(undistorted.data.views.at(3).filename, "pano_front.png");
  EXPECT_EQ(undistorted.data.views.at(8).filename, "pano_down.png");
  EXPECT_EQ(undistorted.data.poses.count(3), 0u);  // the panorama's pose is gone, faces have 4..9
  EXPECT_EQ(undistorted.data.poses.size(), 6u);

  WriteColmapUndistortedWorkspace(data, dir / "images", dir / "workspace");
  const SfmData model = ReadColmapModel(dir / "workspace" / "sparse");
  ASSERT_EQ(model.views.size(), 6u);
  const CameraIntrinsics& face = model.intrinsics.begin()->second;
  EXPECT_EQ(face.width(), 64u);
  ASSERT_EQ(model.structure.size(), 26u);
  size_t observations = 0;
  for (const auto& [id, landmark] : model.structure) {
    ASSERT_EQ(landmark.observations.size(), 1u);
    for (const auto& [view_id, observation] : landmark.observations) {
      ++observations;
      const Eigen::Vector3d X_cam = model.PoseOf(model.views.at(view_id)).ToCamera(landmark.X);
      EXPECT_GT(X_cam.z(), 0);
      EXPECT_LT((face.Project(X_cam) - observation.x).norm(), 1e-6);
      EXPECT_TRUE(observation.x.x() >= -0.5 && observation.x.x() <= 63.5 && observation.x.y() >= -0.5 &&
                  observation.x.y() <= 63.5);
    }
  }
  EXPECT_EQ(observations, 26u);
  for (const auto& [view_id, face_view] : model.views) {
    SCOPED_TRACE(face_view.filename);
    const cv::Mat image = ReadColorImage(dir / "workspace" / "images" / face_view.filename);
    ASSERT_EQ(image.cols, 64);
    const cv::Mat expected = testing::RenderView(model, view_id);
    double sum = 0;
    for (int v = 0; v < 64; ++v) {
      for (int u = 0; u < 64; ++u) {
        for (int c = 0; c < 3; ++c)
          sum += std::abs(image.at<cv::Vec3b>(v, u)[c] - expected.at<cv::Vec3b>(v, u)[c]);
      }
    }
    EXPECT_LT(sum / (64 * 64 * 3), 3.0);
  }
}

// The shared OpenMVS sample stores its vertex colours blue first: projected into the original
// Sceaux Castle image 100_7100.JPG (the sample's 00000.jpg), the stored bytes match the image
// read as BGR much better than as RGB. The sample's K is that of OpenMVG's undistorted images and
// its colours are not sampled from this image alone, so each vertex takes the best-matching pixel
// within 4 pixels of its projection under either order.
TEST(OpenMvsWorkspace, SampleVertexColoursAreStoredBlueFirst) {
  PRUNESFM_REQUIRE_SHARED("formats/openmvs/scene.mvs", sample);
  PRUNESFM_REQUIRE_SHARED("datasets/sceaux_castle/images/100_7100.JPG", image_path);
  const OpenMvsScene scene = ReadOpenMvsScene(sample);
  const cv::Mat image = ReadColorImage(image_path);  // B, G, R
  const OpenMvsScene::Camera& camera = scene.platforms[0].cameras[0];
  const OpenMvsScene::PlatformPose& pose = scene.platforms[0].poses[scene.images[0].pose_id];
  double as_bgr = 0, as_rgb = 0;
  int count = 0;
  for (size_t v = 0; v < scene.vertices.size(); ++v) {
    if (scene.vertices[v].views.front().image_id != 0) continue;
    const Eigen::Vector3d X = pose.R * (scene.vertices[v].X.cast<double>() - pose.C);
    const Eigen::Vector3d x = camera.K * (X / X.z());
    const int u = static_cast<int>(std::lround(x.x())), w = static_cast<int>(std::lround(x.y()));
    if (u < 4 || w < 4 || u >= image.cols - 4 || w >= image.rows - 4) continue;
    const OpenMvsScene::ColorBgr& stored = scene.vertex_colors[v];
    double best_bgr = 1e9, best_rgb = 1e9;
    for (int dv = -4; dv <= 4; ++dv) {
      for (int du = -4; du <= 4; ++du) {
        const cv::Vec3b pixel = image.at<cv::Vec3b>(w + dv, u + du);
        double bgr = 0, rgb = 0;
        for (int c = 0; c < 3; ++c) {
          bgr += std::abs(stored[c] - pixel[c]);
          rgb += std::abs(stored[c] - pixel[2 - c]);
        }
        best_bgr = std::min(best_bgr, bgr);
        best_rgb = std::min(best_rgb, rgb);
      }
    }
    as_bgr += best_bgr;
    as_rgb += best_rgb;
    ++count;
  }
  ASSERT_GT(count, 2000);
  // Measured: 11.2 grey levels per channel as BGR, 20.0 as RGB.
  EXPECT_LT(as_bgr, 0.7 * as_rgb) << "BGR " << as_bgr / (3 * count) << " RGB " << as_rgb / (3 * count);
}

}  // namespace
}  // namespace sfm_pruning
