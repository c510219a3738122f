// OpenMVS .mvs reader and writer: the real sample scene (Sceaux Castle, written by OpenMVG's
// openMVG2openMVS), every archive version, truncated and corrupt files, SfmData conversion.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "sfm_pruning/io/openmvs_conversion.hpp"
#include "sfm_pruning/io/openmvs_scene.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning {
namespace {
namespace fs = std::filesystem;

const char kSample[] = "formats/openmvs/scene.mvs";

void WriteBytes(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// The one-line error a reader throws for `path`, or "" when it does not throw.
std::string ReadError(const fs::path& path) {
  try {
    ReadOpenMvsScene(path);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

void ExpectOneLineErrorNaming(const std::string& message, const fs::path& path, const std::string& problem) {
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
  EXPECT_NE(message.find(problem), std::string::npos) << message;
}

TEST(OpenMvsScene, ReadsTheSharedSample) {
  PRUNESFM_REQUIRE_SHARED(kSample, sample);
  const OpenMvsScene scene = ReadOpenMvsScene(sample);
  EXPECT_EQ(scene.version, 3u);
  ASSERT_EQ(scene.platforms.size(), 1u);
  const OpenMvsScene::Platform& platform = scene.platforms[0];
  EXPECT_EQ(platform.name, "platform0");
  ASSERT_EQ(platform.cameras.size(), 1u);
  const OpenMvsScene::Camera& camera = platform.cameras[0];
  EXPECT_EQ(camera.name, "EASTMAN KODAK COMPANY - KODAK Z612 ZOOM DIGITAL CAMERA");
  EXPECT_EQ(camera.width, 2832u);
  EXPECT_EQ(camera.height, 2128u);
  EXPECT_DOUBLE_EQ(camera.K(0, 0), 2985.3283429154812);
  EXPECT_DOUBLE_EQ(camera.K(1, 1), 2985.3283429154812);
  EXPECT_DOUBLE_EQ(camera.K(0, 2), 1452.1358632578272);
  EXPECT_DOUBLE_EQ(camera.K(1, 2), 1125.0339388744535);
  EXPECT_EQ(camera.K(2, 2), 1.0);
  EXPECT_EQ(camera.R, Eigen::Matrix3d::Identity());
  EXPECT_EQ(camera.C, Eigen::Vector3d::Zero());
  ASSERT_EQ(platform.poses.size(), 11u);
  for (const OpenMvsScene::PlatformPose& pose : platform.poses) {
    EXPECT_LT((pose.R * pose.R.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-12);
    EXPECT_NEAR(pose.R.determinant(), 1.0, 1e-12);
  }
  EXPECT_DOUBLE_EQ(platform.poses[10].C.x(), 4.94882787926134);
  ASSERT_EQ(scene.images.size(), 11u);
  for (uint32_t i = 0; i < 11; ++i) {
    char name[32];
    std::snprintf(name, sizeof(name), "images/%05u.jpg", i);
    EXPECT_EQ(scene.images[i].name, name);
    EXPECT_EQ(scene.images[i].platform_id, 0u);
    EXPECT_EQ(scene.images[i].camera_id, 0u);
    EXPECT_EQ(scene.images[i].pose_id, i);
    EXPECT_EQ(scene.images[i].id, i);
  }
  ASSERT_EQ(scene.vertices.size(), 12683u);
  EXPECT_FLOAT_EQ(scene.vertices[0].X.x(), -0.10928363353013992f);
  ASSERT_EQ(scene.vertices[0].views.size(), 10u);
  EXPECT_EQ(scene.vertices[0].views[9].image_id, 10u);
  EXPECT_EQ(scene.vertices[0].views[0].confidence, 289.0f);
  size_t observations = 0;
  for (const OpenMvsScene::Vertex& vertex : scene.vertices) {
    EXPECT_GE(vertex.views.size(), 2u);
    observations += vertex.views.size();
  }
  EXPECT_GT(observations, 3 * scene.vertices.size());
  EXPECT_TRUE(scene.vertex_normals.empty());
  ASSERT_EQ(scene.vertex_colors.size(), 12683u);
  EXPECT_EQ(scene.vertex_colors[1], (OpenMvsScene::ColorBgr{110, 72, 49}));
  EXPECT_TRUE(scene.lines.empty());
  EXPECT_EQ(scene.transform, Eigen::Matrix4d::Identity());
}

TEST(OpenMvsScene, RewritesTheSharedSampleByteForByte) {
  PRUNESFM_REQUIRE_SHARED(kSample, sample);
  const fs::path dir = testing::ScratchDir("openmvs_sample_roundtrip");
  const OpenMvsScene scene = ReadOpenMvsScene(sample);
  WriteOpenMvsScene(scene, dir / "scene.mvs");
  EXPECT_EQ(ReadFileToString(dir / "scene.mvs"), ReadFileToString(sample));
  // Read again, write again: still the same bytes (the struct holds every field).
  WriteOpenMvsScene(ReadOpenMvsScene(dir / "scene.mvs"), dir / "again.mvs");
  EXPECT_EQ(ReadFileToString(dir / "again.mvs"), ReadFileToString(sample));
}

TEST(OpenMvsScene, SampleConvertsToAModelWithTheSamePoses) {
  PRUNESFM_REQUIRE_SHARED(kSample, sample);
  const OpenMvsScene scene = ReadOpenMvsScene(sample);
  const SfmData data = SfmDataFromOpenMvsScene(scene, sample.string());
  ASSERT_EQ(data.PosedViewIds().size(), 11u);
  ASSERT_EQ(data.intrinsics.size(), 1u);
  EXPECT_EQ(data.intrinsics.at(0), CameraIntrinsics::Pinhole(2832, 2128, 2985.3283429154812,
                                                             1452.1358632578272, 1125.0339388744535));
  EXPECT_EQ(data.views.at(3).filename, "00003.jpg");
  EXPECT_EQ(data.views.at(3).local_path, "images");
  EXPECT_EQ(data.poses.at(10).center, scene.platforms[0].poses[10].C);
  ASSERT_EQ(data.structure.size(), 12683u);
  EXPECT_EQ(data.structure.at(1).color, (std::array<uint8_t, 3>{49, 72, 110}));
  // Every vertex lies in front of the cameras that see it and projects inside their images but
  // for a few near the border (0.3 %: OpenMVG's undistorted images crop the border).
  size_t inside = 0, total = 0;
  for (const auto& [id, landmark] : data.structure) {
    for (const auto& [view_id, observation] : landmark.observations) {
      ++total;
      inside += observation.x.x() >= 0 && observation.x.x() < 2832 && observation.x.y() >= 0 &&
                observation.x.y() < 2128;
    }
  }
  size_t views = 0;
  for (const OpenMvsScene::Vertex& vertex : scene.vertices) views += vertex.views.size();
  EXPECT_EQ(total, views);
  EXPECT_GT(inside, 0.99 * total);
  // Export back: same cameras, poses, image names and vertices.
  const OpenMvsScene exported = OpenMvsSceneFromSfmData(data, "", 3);
  ASSERT_EQ(exported.images.size(), 11u);
  EXPECT_EQ(exported.images[4].name, "images/00004.jpg");
  EXPECT_EQ(exported.platforms[0].cameras[0].K, scene.platforms[0].cameras[0].K);
  EXPECT_EQ(exported.platforms[0].poses[7].R, scene.platforms[0].poses[7].R);
  ASSERT_EQ(exported.vertices.size(), scene.vertices.size());
  EXPECT_EQ(exported.vertices[5].X, scene.vertices[5].X);
  EXPECT_EQ(exported.vertex_colors, scene.vertex_colors);
}

// A scene that fills every field some version stores.
OpenMvsScene FullScene(uint32_t version) {
  OpenMvsScene scene;
  scene.version = version;
  scene.reserved = version >= 1 ? 7 : 0;
  OpenMvsScene::Platform platform;
  platform.name = "rig";
  OpenMvsScene::Camera camera;
  camera.name = "left";
  camera.band_name = "RGB";
  camera.width = 640;
  camera.height = 480;
  camera.K << 500, 0, 319.5, 0, 510, 239.25, 0, 0, 1;
  camera.R = Eigen::AngleAxisd(0.1, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  camera.C = {0.1, -0.2, 0.3};
  platform.cameras = {camera, camera};
  platform.cameras[1].name = "right";
  for (int k = 0; k < 3; ++k) {
    platform.poses.push_back({Eigen::AngleAxisd(0.3 * k, Eigen::Vector3d::UnitY()).toRotationMatrix(),
                              Eigen::Vector3d(k, 2.0 * k, -1.0)});
  }
  scene.platforms = {platform};
  for (uint32_t i = 0; i < 3; ++i) {
    OpenMvsScene::Image image;
    image.name = "images/" + std::to_string(i) + ".png";
    image.mask_name = i == 1 ? "masks/1.png" : "";
    image.platform_id = 0;
    image.camera_id = i % 2;
    image.pose_id = i == 2 ? kOpenMvsNoId : i;
    image.id = 10 + i;
    image.min_depth = 1.5f;
    image.avg_depth = 2.5f + i;
    image.max_depth = 9.0f;
    image.view_scores = {{(i + 1) % 3, 42, 1.0f, 0.25f, 0.5f, 3.0f}};
    scene.images.push_back(image);
  }
  for (int v = 0; v < 4; ++v) {
    OpenMvsScene::Vertex vertex;
    vertex.X = Eigen::Vector3f(0.5f * v, -1.25f, 3.0f + v);
    vertex.views = {{0, 0.5f}, {static_cast<uint32_t>(1 + v % 2), 0.0f}};
    scene.vertices.push_back(vertex);
    scene.vertex_normals.push_back(Eigen::Vector3f(0, 0, -1));
    scene.vertex_colors.push_back({static_cast<uint8_t>(v), 128, 255});
  }
  if (version >= 1) {
    OpenMvsScene::Line line;
    line.pt1 = {1, 2, 3};
    line.pt2 = {4, 5, 6};
    line.views = {{1, 1.0f}};
    scene.lines = {line};
    scene.line_normals = {Eigen::Vector3f(1, 0, 0)};
    scene.line_colors = {{9, 8, 7}};
  }
  if (version >= 2) scene.transform(0, 3) = 12.5;
  if (version >= 6) {
    scene.bounding_box.min = {-1, -2, -3};
    scene.bounding_box.max = {1, 2, 3};
  }
  if (version < 4) scene.platforms[0].cameras[0].band_name = scene.platforms[0].cameras[1].band_name = "";
  if (version < 1) scene.platforms[0].cameras[0].width = scene.platforms[0].cameras[1].width = 0;
  if (version < 1) scene.platforms[0].cameras[0].height = scene.platforms[0].cameras[1].height = 0;
  for (OpenMvsScene::Image& image : scene.images) {
    if (version < 5) image.mask_name.clear();
    if (version < 3) image.id = kOpenMvsNoId;
    if (version < 7) {
      image.min_depth = image.avg_depth = image.max_depth = 0;
      image.view_scores.clear();
    }
  }
  return scene;
}

void ExpectScenesEqual(const OpenMvsScene& a, const OpenMvsScene& b) {
  EXPECT_EQ(a.version, b.version);
  EXPECT_EQ(a.reserved, b.reserved);
  ASSERT_EQ(a.platforms.size(), b.platforms.size());
  for (size_t p = 0; p < a.platforms.size(); ++p) {
    EXPECT_EQ(a.platforms[p].name, b.platforms[p].name);
    ASSERT_EQ(a.platforms[p].cameras.size(), b.platforms[p].cameras.size());
    for (size_t c = 0; c < a.platforms[p].cameras.size(); ++c) {
      const OpenMvsScene::Camera& x = a.platforms[p].cameras[c];
      const OpenMvsScene::Camera& y = b.platforms[p].cameras[c];
      EXPECT_EQ(x.name, y.name);
      EXPECT_EQ(x.band_name, y.band_name);
      EXPECT_EQ(x.width, y.width);
      EXPECT_EQ(x.height, y.height);
      EXPECT_EQ(x.K, y.K);
      EXPECT_EQ(x.R, y.R);
      EXPECT_EQ(x.C, y.C);
    }
    ASSERT_EQ(a.platforms[p].poses.size(), b.platforms[p].poses.size());
    for (size_t k = 0; k < a.platforms[p].poses.size(); ++k) {
      EXPECT_EQ(a.platforms[p].poses[k].R, b.platforms[p].poses[k].R);
      EXPECT_EQ(a.platforms[p].poses[k].C, b.platforms[p].poses[k].C);
    }
  }
  ASSERT_EQ(a.images.size(), b.images.size());
  for (size_t i = 0; i < a.images.size(); ++i) {
    const OpenMvsScene::Image& x = a.images[i];
    const OpenMvsScene::Image& y = b.images[i];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.mask_name, y.mask_name);
    EXPECT_EQ(x.platform_id, y.platform_id);
    EXPECT_EQ(x.camera_id, y.camera_id);
    EXPECT_EQ(x.pose_id, y.pose_id);
    EXPECT_EQ(x.id, y.id);
    EXPECT_EQ(x.avg_depth, y.avg_depth);
    ASSERT_EQ(x.view_scores.size(), y.view_scores.size());
    for (size_t k = 0; k < x.view_scores.size(); ++k) {
      EXPECT_EQ(x.view_scores[k].id, y.view_scores[k].id);
      EXPECT_EQ(x.view_scores[k].points, y.view_scores[k].points);
      EXPECT_EQ(x.view_scores[k].score, y.view_scores[k].score);
    }
  }
  ASSERT_EQ(a.vertices.size(), b.vertices.size());
  for (size_t v = 0; v < a.vertices.size(); ++v) {
    EXPECT_EQ(a.vertices[v].X, b.vertices[v].X);
    ASSERT_EQ(a.vertices[v].views.size(), b.vertices[v].views.size());
    for (size_t k = 0; k < a.vertices[v].views.size(); ++k) {
      EXPECT_EQ(a.vertices[v].views[k].image_id, b.vertices[v].views[k].image_id);
      EXPECT_EQ(a.vertices[v].views[k].confidence, b.vertices[v].views[k].confidence);
    }
  }
  EXPECT_EQ(a.vertex_normals, b.vertex_normals);
  EXPECT_EQ(a.vertex_colors, b.vertex_colors);
  ASSERT_EQ(a.lines.size(), b.lines.size());
  for (size_t l = 0; l < a.lines.size(); ++l) {
    EXPECT_EQ(a.lines[l].pt1, b.lines[l].pt1);
    EXPECT_EQ(a.lines[l].pt2, b.lines[l].pt2);
    EXPECT_EQ(a.lines[l].views.size(), b.lines[l].views.size());
  }
  EXPECT_EQ(a.line_normals, b.line_normals);
  EXPECT_EQ(a.line_colors, b.line_colors);
  EXPECT_EQ(a.transform, b.transform);
  EXPECT_EQ(a.bounding_box.min, b.bounding_box.min);
  EXPECT_EQ(a.bounding_box.max, b.bounding_box.max);
}

TEST(OpenMvsScene, EveryVersionRoundTrips) {
  const fs::path dir = testing::ScratchDir("openmvs_versions");
  size_t previous_size = 0;
  for (uint32_t version = 0; version <= kOpenMvsNewestVersion; ++version) {
    SCOPED_TRACE("version " + std::to_string(version));
    const OpenMvsScene scene = FullScene(version);
    const fs::path path = dir / ("v" + std::to_string(version) + ".mvs");
    WriteOpenMvsScene(scene, path);
    const std::string bytes = ReadFileToString(path);
    // Version 0 has no header; later versions only add fields.
    EXPECT_EQ(bytes.compare(0, 4, "MVSI"), version == 0 ? bytes.compare(0, 4, "MVSI") : 0);
    EXPECT_GE(bytes.size(), previous_size);
    previous_size = bytes.size();
    const OpenMvsScene read = ReadOpenMvsScene(path);
    ExpectScenesEqual(scene, read);
    WriteOpenMvsScene(read, dir / "again.mvs");
    EXPECT_EQ(ReadFileToString(dir / "again.mvs"), bytes);
  }
  // A headerless archive is only recognised under the .mvs extension, as OpenMVS does.
  fs::copy_file(dir / "v0.mvs", dir / "v0.bin");
  ExpectOneLineErrorNaming(ReadError(dir / "v0.bin"), dir / "v0.bin", "not an OpenMVS scene");
}

TEST(OpenMvsScene, TruncatedFilesGiveOneLineErrors) {
  const fs::path dir = testing::ScratchDir("openmvs_truncated");
  WriteOpenMvsScene(FullScene(kOpenMvsNewestVersion), dir / "full.mvs");
  const std::string bytes = ReadFileToString(dir / "full.mvs");
  for (size_t size = 0; size < bytes.size(); size += 1 + size / 7) {
    SCOPED_TRACE("size " + std::to_string(size));
    const fs::path path = dir / "cut.mvs";
    WriteBytes(path, bytes.substr(0, size));
    const std::string message = ReadError(path);
    ASSERT_FALSE(message.empty());
    ExpectOneLineErrorNaming(message, path, size >= 4 ? "truncated" : "");
  }
  ExpectOneLineErrorNaming(ReadError(dir / "missing.mvs"), dir / "missing.mvs", "");
}

TEST(OpenMvsScene, CorruptFilesGiveOneLineErrors) {
  const fs::path dir = testing::ScratchDir("openmvs_corrupt");
  WriteOpenMvsScene(FullScene(3), dir / "good.mvs");
  const std::string good = ReadFileToString(dir / "good.mvs");
  const fs::path path = dir / "bad.mvs";

  std::string newer = good;
  newer[4] = 99;
  WriteBytes(path, newer);
  ExpectOneLineErrorNaming(ReadError(path), path, "version 99 is newer");

  std::string huge_count = good;  // the platform count right after the 12-byte header
  const uint64_t count = uint64_t{1} << 60;
  std::memcpy(&huge_count[12], &count, 8);
  WriteBytes(path, huge_count);
  ExpectOneLineErrorNaming(ReadError(path), path, "platforms has a count of 1152921504606846976");

  WriteBytes(path, good + "xyz");
  ExpectOneLineErrorNaming(ReadError(path), path, "3 unexpected bytes after the scene");

  OpenMvsScene dangling = FullScene(3);
  dangling.images[1].platform_id = 4;
  WriteOpenMvsScene(dangling, path);
  ExpectOneLineErrorNaming(ReadError(path), path, "image 1 (images/1.png) names platform 4");

  OpenMvsScene unsorted = FullScene(3);
  unsorted.vertices[2].views = {{2, 0.f}, {0, 0.f}};
  WriteOpenMvsScene(unsorted, path);
  ExpectOneLineErrorNaming(ReadError(path), path, "vertex 2 lists its views out of order");

  OpenMvsScene unseen = FullScene(3);
  unseen.vertices[0].views = {{5, 0.f}};
  WriteOpenMvsScene(unseen, path);
  ExpectOneLineErrorNaming(ReadError(path), path, "vertex 0 is seen by image 5 but there are 3 images");

  OpenMvsScene colors = FullScene(3);
  colors.vertex_colors.pop_back();
  WriteOpenMvsScene(colors, path);
  ExpectOneLineErrorNaming(ReadError(path), path, "3 vertex colours for 4 vertices");

  OpenMvsScene future = FullScene(3);
  future.version = 8;
  EXPECT_THROW(WriteOpenMvsScene(future, path), Error);
}

SfmData UndistortedModel() {
  SfmData data;
  data.intrinsics[3] = CameraIntrinsics::Pinhole(640, 480, 500.0, 320.25, 241.5);
  data.intrinsics[5] = CameraIntrinsics(CameraModel::kPinholeFxFy, 800, 600, {700.0, 710.0, 399.5, 300.5});
  for (IndexT v = 0; v < 4; ++v) {
    View view;
    view.id_view = v;
    view.id_intrinsic = v < 2 ? 3 : 5;
    view.id_pose = v == 3 ? kUndefinedIndex : v;
    view.local_path = v == 1 ? "sub" : "";
    view.filename = "img" + std::to_string(v) + ".jpg";
    view.width = v < 2 ? 640 : 800;
    view.height = v < 2 ? 480 : 600;
    data.views[v] = view;
    if (v < 3) {
      data.poses[v] =
          Pose(Eigen::AngleAxisd(0.2 * v, Eigen::Vector3d(0, 1, 0.1).normalized()).toRotationMatrix(),
               Eigen::Vector3d(0.5 * v, 0.1, -4.0));
    }
  }
  for (IndexT k = 0; k < 5; ++k) {
    Landmark landmark;
    landmark.X = Eigen::Vector3d(0.25 * k - 0.5, 0.1 * k, 1.0 + 0.5 * k);
    landmark.color = {static_cast<uint8_t>(10 * k), 20, 200};
    for (IndexT v = 0; v < 4; ++v) {
      if ((k + v) % 4 == 0) continue;
      if (data.poses.count(v) == 0) {
        landmark.observations[v] = {Eigen::Vector2d(1, 1), k};
        continue;
      }
      landmark.observations[v] = {
          data.intrinsics.at(data.views[v].id_intrinsic).Project(data.poses[v].ToCamera(landmark.X)), k};
    }
    data.structure[10 + k] = landmark;
  }
  return data;
}

TEST(OpenMvsScene, ExportedModelReadsBackWithTheSameCamerasAndPoses) {
  const SfmData data = UndistortedModel();
  const fs::path dir = testing::ScratchDir("openmvs_export");
  WriteOpenMvsScene(OpenMvsSceneFromSfmData(data, "images"), dir / "scene.mvs");
  const OpenMvsScene scene = ReadOpenMvsScene(dir / "scene.mvs");
  EXPECT_EQ(scene.version, kOpenMvsExportVersion);
  ASSERT_EQ(scene.platforms.size(), 2u);
  ASSERT_EQ(scene.images.size(), 3u);  // the unposed view is left out
  EXPECT_EQ(scene.images[1].name, "images/sub/img1.jpg");
  EXPECT_EQ(scene.images[2].platform_id, 1u);
  EXPECT_EQ(scene.images[2].pose_id, 0u);
  const SfmData read = SfmDataFromOpenMvsScene(scene, "scene.mvs");
  ASSERT_EQ(read.views.size(), 3u);
  for (IndexT v = 0; v < 3; ++v) {
    SCOPED_TRACE(v);
    EXPECT_EQ(read.IntrinsicsOf(read.views.at(v)), data.IntrinsicsOf(data.views.at(v)));
    EXPECT_EQ(read.PoseOf(read.views.at(v)).rotation, data.PoseOf(data.views.at(v)).rotation);
    EXPECT_EQ(read.PoseOf(read.views.at(v)).center, data.PoseOf(data.views.at(v)).center);
    EXPECT_EQ(read.views.at(v).RelativeImagePath(), "images/" + data.views.at(v).RelativeImagePath());
  }
  ASSERT_EQ(read.structure.size(), 5u);
  IndexT k = 0;
  for (const auto& [id, landmark] : read.structure) {
    const Landmark& original = data.structure.at(10 + k++);
    EXPECT_LT((landmark.X - original.X).norm(), 1e-6);  // float32 positions
    EXPECT_EQ(landmark.color, original.color);
    size_t posed_observations = 0;
    for (const auto& [view_id, observation] : original.observations) {
      if (data.poses.count(view_id) == 0) continue;
      ++posed_observations;
      ASSERT_EQ(landmark.observations.count(view_id), 1u);
      EXPECT_LT((landmark.observations.at(view_id).x - observation.x).norm(), 1e-3);
    }
    EXPECT_EQ(landmark.observations.size(), posed_observations);
  }
}

TEST(OpenMvsScene, ExportRefusesDistortedCameras) {
  SfmData data = UndistortedModel();
  data.intrinsics[3] =
      CameraIntrinsics(CameraModel::kPinholeRadialK1, 640, 480, {500.0, 320.25, 241.5, -0.1});
  try {
    OpenMvsSceneFromSfmData(data, "images");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("pinhole_radial_k1 camera with distortion"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace sfm_pruning
