// Our COLMAP undistorted workspace against the real COLMAP 3.8: model_analyzer accepts it, and it
// agrees with what `colmap image_undistorter` makes of the same distorted model and images.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <string>

#include <opencv2/imgproc.hpp>

#include "export/rendered_scene.hpp"
#include "sfm_pruning/export/dense_workspaces.hpp"
#include "sfm_pruning/export/image_files.hpp"
#include "sfm_pruning/io/colmap_model.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning {
namespace {
namespace fs = std::filesystem;

const fs::path kColmapBinary = "/usr/bin/colmap";

int RunColmapTool(const std::string& arguments, const fs::path& log) {
  const std::string command = "QT_QPA_PLATFORM=offscreen " + kColmapBinary.string() + " " + arguments +
                              " > " + log.string() + " 2>&1";
  return std::system(command.c_str());
}

// Mean absolute difference (grey levels per channel) between `image` (seen through `camera`) and
// `other` (through `other_camera`), both looking from the same pose: each pixel of `image` at
// least `margin` inside is compared with `other` sampled bilinearly along the same ray.
double MeanDifferenceAlongRays(const cv::Mat& image, const CameraIntrinsics& camera, const cv::Mat& other,
                               const CameraIntrinsics& other_camera, int margin) {
  cv::Mat map_x(image.rows, image.cols, CV_32FC1), map_y(image.rows, image.cols, CV_32FC1);
  for (int v = 0; v < image.rows; ++v) {
    for (int u = 0; u < image.cols; ++u) {
      const Eigen::Vector2d x =
          other_camera.NormalizedToPixel(camera.PixelToNormalized(Eigen::Vector2d(u, v)));
      map_x.at<float>(v, u) = static_cast<float>(x.x());
      map_y.at<float>(v, u) = static_cast<float>(x.y());
    }
  }
  cv::Mat resampled;
  cv::remap(other, resampled, map_x, map_y, cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar::all(0));
  double sum = 0;
  int count = 0;
  for (int v = margin; v < image.rows - margin; ++v) {
    for (int u = margin; u < image.cols - margin; ++u) {
      const float sx = map_x.at<float>(v, u), sy = map_y.at<float>(v, u);
      if (sx < 0 || sy < 0 || sx > other.cols - 1 || sy > other.rows - 1) continue;  // outside the other view
      for (int c = 0; c < 3; ++c)
        sum += std::abs(image.at<cv::Vec3b>(v, u)[c] - resampled.at<cv::Vec3b>(v, u)[c]);
      count += 3;
    }
  }
  return count == 0 ? 1e9 : sum / count;
}

TEST(ColmapWorkspaceInterop, ColmapAcceptsOurUndistortedWorkspaceAndAgreesWithItsOwn) {
  if (!fs::exists(kColmapBinary)) GTEST_SKIP() << "COLMAP not installed at " << kColmapBinary;
  const fs::path dir = testing::ScratchDir("interop_workspace");
  // COLMAP's RADIAL camera (f, cx, cy, k1, k2): barrel distortion a real lens would have.
  const CameraIntrinsics distorted(CameraModel::kPinholeRadialK3, 320, 240,
                                   {280.0, 161.5, 118.0, -0.22, 0.06, 0.0});
  const SfmData data = testing::MakeRenderedScene(distorted, dir / "images");

  WriteColmapUndistortedWorkspace(data, dir / "images", dir / "ours");
  ASSERT_EQ(
      RunColmapTool("model_analyzer --path " + (dir / "ours" / "sparse").string(), dir / "analyzer.log"), 0)
      << ReadFileToString(dir / "analyzer.log");
  const std::string analysis = ReadFileToString(dir / "analyzer.log");
  EXPECT_NE(analysis.find("Cameras: 1"), std::string::npos) << analysis;
  EXPECT_NE(analysis.find("Registered images: 3"), std::string::npos) << analysis;
  EXPECT_NE(analysis.find("Points: 40"), std::string::npos) << analysis;
  EXPECT_NE(analysis.find("Observations: 120"), std::string::npos) << analysis;

  // COLMAP's own undistortion of the same model and images.
  WriteColmapModel(data, dir / "distorted", ColmapModelFormat::kBinary);
  ASSERT_EQ(RunColmapTool("image_undistorter --image_path " + (dir / "images").string() + " --input_path " +
                              (dir / "distorted").string() + " --output_path " + (dir / "colmap").string() +
                              " --output_type COLMAP",
                          dir / "undistorter.log"),
            0)
      << ReadFileToString(dir / "undistorter.log");
  // The same layout and the same stereo configuration files, byte for byte.
  for (const char* file : {"sparse/cameras.bin", "sparse/images.bin", "sparse/points3D.bin",
                           "stereo/patch-match.cfg", "stereo/fusion.cfg"}) {
    EXPECT_TRUE(fs::is_regular_file(dir / "colmap" / file)) << file;
    EXPECT_TRUE(fs::is_regular_file(dir / "ours" / file)) << file;
  }
  EXPECT_EQ(ReadFileToString(dir / "ours/stereo/patch-match.cfg"),
            ReadFileToString(dir / "colmap/stereo/patch-match.cfg"));
  EXPECT_EQ(ReadFileToString(dir / "ours/stereo/fusion.cfg"),
            ReadFileToString(dir / "colmap/stereo/fusion.cfg"));

  const SfmData ours = ReadColmapModel(dir / "ours" / "sparse");
  const SfmData theirs = ReadColmapModel(dir / "colmap" / "sparse");
  const CameraIntrinsics& our_camera = ours.intrinsics.begin()->second;
  const CameraIntrinsics& their_camera = theirs.intrinsics.begin()->second;
  EXPECT_FALSE(their_camera.HasDistortion());
  ::testing::Test::RecordProperty("colmap_camera", std::to_string(their_camera.width()) + "x" +
                                                       std::to_string(their_camera.height()) + " f " +
                                                       std::to_string(their_camera.FocalX()));
  // Same poses and 3D points; observations moved to the same rays (different K).
  ASSERT_EQ(theirs.views.size(), 3u);
  for (const auto& [id, landmark] : ours.structure) {
    const Landmark& other = theirs.structure.at(id);
    EXPECT_LT((landmark.X - other.X).norm(), 1e-12);
    for (const auto& [view_id, observation] : landmark.observations) {
      const Eigen::Vector2d ray = our_camera.PixelToNormalized(observation.x);
      const Eigen::Vector2d their_ray = their_camera.PixelToNormalized(other.observations.at(view_id).x);
      EXPECT_LT((ray - their_ray).norm(), 1e-9);
    }
  }
  // The images show the same thing along the same rays, and both match the rendered truth.
  for (const auto& [view_id, view] : ours.views) {
    SCOPED_TRACE(view.filename);
    const cv::Mat our_image = ReadColorImage(dir / "ours" / "images" / view.filename);
    const cv::Mat their_image = ReadColorImage(dir / "colmap" / "images" / view.filename);
    const double ours_vs_colmap =
        MeanDifferenceAlongRays(our_image, our_camera, their_image, their_camera, 2);
    SfmData truth = data;
    truth.intrinsics[0] = our_camera;
    const double ours_vs_truth =
        MeanDifferenceAlongRays(our_image, our_camera, testing::RenderView(truth, view_id), our_camera, 0);
    truth.intrinsics[0] = their_camera;
    const double colmap_vs_truth = MeanDifferenceAlongRays(
        their_image, their_camera, testing::RenderView(truth, view_id), their_camera, 0);
    std::printf("%s: ours vs COLMAP %.2f, ours vs truth %.2f, COLMAP vs truth %.2f grey levels\n",
                view.filename.c_str(), ours_vs_colmap, ours_vs_truth, colmap_vs_truth);
    EXPECT_LT(ours_vs_colmap, 2.0);
    EXPECT_LT(ours_vs_truth, colmap_vs_truth + 0.5);
  }
}

}  // namespace
}  // namespace sfm_pruning
