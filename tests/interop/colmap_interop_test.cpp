// Interoperability with the real COLMAP 3.8 binary: it must read the models we write, we must
// read what it writes, and we must read a database it builds from features we give it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <string>
#include <vector>

#include "sfm_pruning/io/colmap_camera.hpp"
#include "sfm_pruning/io/colmap_database.hpp"
#include "sfm_pruning/io/colmap_model.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning {
namespace {
namespace fs = std::filesystem;

const fs::path kColmap = "/usr/bin/colmap";

#define REQUIRE_COLMAP()                                                          \
  if (!fs::exists(kColmap)) {                                                     \
    GTEST_SKIP() << "COLMAP not installed at " << kColmap << "; interop skipped"; \
  }

// Runs COLMAP headless with its output in `log`; returns the exit status.
int RunColmap(const std::string& arguments, const fs::path& log) {
  const std::string command =
      "QT_QPA_PLATFORM=offscreen " + kColmap.string() + " " + arguments + " > " + log.string() + " 2>&1";
  return std::system(command.c_str());
}

std::string ReadLog(const fs::path& log) {
  std::ifstream in(log);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// World -> camera rotation of a camera at `center` looking at the origin, image y pointing
// roughly along world +y.
Eigen::Matrix3d LookAtOrigin(const Eigen::Vector3d& center) {
  const Eigen::Vector3d z = (-center).normalized();
  const Eigen::Vector3d x = Eigen::Vector3d::UnitY().cross(z).normalized();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Matrix3d R;
  R << x.transpose(), y.transpose(), z.transpose();
  return R;
}

// Three cameras on an arc around 60 points spread in a unit cube (deterministic, no RNG),
// every point seen by every camera; the observation of point k is feature k of each view.
SfmData SyntheticScene() {
  SfmData data;
  data.intrinsics[0] = CameraIntrinsics::Pinhole(640, 480, 500.0, 319.5, 239.5);
  const double angles[] = {-0.35, 0.0, 0.4};
  for (IndexT v = 0; v < 3; ++v) {
    const Eigen::Vector3d center(6 * std::sin(angles[v]), 0.4 * v - 0.3, -6 * std::cos(angles[v]));
    data.poses[v] = Pose(LookAtOrigin(center), center);
    View view;
    view.id_view = v;
    view.id_pose = v;
    view.id_intrinsic = 0;
    view.filename = "image" + std::to_string(v) + ".pgm";
    view.width = 640;
    view.height = 480;
    data.views[v] = view;
  }
  for (IndexT k = 0; k < 60; ++k) {
    Landmark landmark;
    landmark.X = {std::sin(1.3 * k + 0.2), std::cos(2.1 * k), std::sin(0.7 * k + 1.0) * std::cos(0.3 * k)};
    landmark.color = {static_cast<uint8_t>(4 * k), 100, static_cast<uint8_t>(255 - 4 * k)};
    landmark.error = 0.01 * k;
    for (const auto& [v, view] : data.views) {
      landmark.observations[v] = {data.intrinsics[0].Project(data.poses[v].ToCamera(landmark.X)), k};
    }
    data.structure[k] = landmark;
  }
  return data;
}

void ExpectModelsMatch(const SfmData& expected, const SfmData& actual) {
  EXPECT_EQ(actual.views, expected.views);
  EXPECT_EQ(actual.intrinsics, expected.intrinsics);
  ASSERT_EQ(actual.poses.size(), expected.poses.size());
  for (const auto& [id, pose] : expected.poses) {
    EXPECT_LT((actual.poses.at(id).rotation - pose.rotation).norm(), 1e-14);
    EXPECT_LT((actual.poses.at(id).center - pose.center).norm(), 1e-13);
  }
  ASSERT_EQ(actual.structure.size(), expected.structure.size());
  for (const auto& [id, landmark] : expected.structure) {
    const Landmark& other = actual.structure.at(id);
    EXPECT_EQ(other.X, landmark.X);
    EXPECT_EQ(other.color, landmark.color);
    ASSERT_EQ(other.observations.size(), landmark.observations.size());
    for (const auto& [view_id, observation] : landmark.observations) {
      // x + 0.5 - 0.5 may lose the last bit when it crosses a power of two.
      EXPECT_LT((other.observations.at(view_id).x - observation.x).norm(), 1e-12);
      EXPECT_EQ(other.observations.at(view_id).id_feat, observation.id_feat);
    }
  }
}

TEST(ColmapInterop, ColmapConvertsAndAnalyzesOurModels) {
  REQUIRE_COLMAP();
  const SfmData scene = SyntheticScene();
  const fs::path dir = testing::ScratchDir("interop_model");
  for (ColmapModelFormat format : {ColmapModelFormat::kBinary, ColmapModelFormat::kText}) {
    const std::string ours = format == ColmapModelFormat::kBinary ? "ours_bin" : "ours_txt";
    SCOPED_TRACE(ours);
    WriteColmapModel(scene, dir / ours, format);
    const SfmData written = ReadColmapModel(dir / ours);
    ExpectModelsMatch(scene, written);
    ASSERT_EQ(RunColmap("model_analyzer --path " + (dir / ours).string(), dir / "analyzer.log"), 0)
        << ReadLog(dir / "analyzer.log");
    EXPECT_NE(ReadLog(dir / "analyzer.log").find("Registered images: 3"), std::string::npos)
        << ReadLog(dir / "analyzer.log");
    for (const char* type : {"TXT", "BIN"}) {
      const fs::path out = dir / (ours + "_to_" + type);
      fs::create_directories(out);
      ASSERT_EQ(RunColmap("model_converter --input_path " + (dir / ours).string() + " --output_path " +
                              out.string() + " --output_type " + type,
                          dir / "converter.log"),
                0)
          << ReadLog(dir / "converter.log");
      ExpectModelsMatch(written, ReadColmapModel(out));
    }
  }
}

// A binary PGM of mid-grey: COLMAP's image reader only needs a decodable file of the right size.
void WritePgm(const fs::path& path, int width, int height) {
  std::ofstream out(path, std::ios::binary);
  out << "P5\n" << width << " " << height << "\n255\n";
  out << std::string(static_cast<size_t>(width) * height, static_cast<char>(128));
}

Descriptor MakeDescriptor(IndexT feature) {
  Descriptor descriptor;
  for (int d = 0; d < kDescriptorSize; ++d)
    descriptor[d] = static_cast<uint8_t>((feature * 7 + d * 13) % 256);
  return descriptor;
}

TEST(ColmapInterop, WeReadTheDatabaseColmapBuildsFromOurFeatures) {
  REQUIRE_COLMAP();
  const SfmData scene = SyntheticScene();
  const fs::path dir = testing::ScratchDir("interop_database");
  fs::create_directories(dir / "images");
  fs::create_directories(dir / "features");
  // feature_importer text format, in COLMAP's pixel convention: "N 128", then per keypoint
  // "X Y SCALE ORIENTATION" and 128 descriptor values.
  for (const auto& [v, view] : scene.views) {
    WritePgm(dir / "images" / view.filename, 640, 480);
    std::ofstream out(dir / "features" / (view.filename + ".txt"));
    out << std::setprecision(9) << scene.structure.size() << " 128\n";
    for (const auto& [k, landmark] : scene.structure) {
      const Eigen::Vector2d colmap = ToColmapPixel(landmark.observations.at(v).x);
      out << colmap.x() << " " << colmap.y() << " " << 1.5 + 0.01 * k << " " << 0.02 * k;
      for (uint8_t value : MakeDescriptor(k)) out << " " << static_cast<int>(value);
      out << "\n";
    }
  }
  // Raw matches: the same point is the same feature index in every image.
  {
    std::ofstream out(dir / "matches.txt");
    for (const auto& [a, b] : {std::pair<IndexT, IndexT>{0, 1}, {0, 2}, {1, 2}}) {
      out << scene.views.at(a).filename << " " << scene.views.at(b).filename << "\n";
      for (IndexT k = 0; k < scene.structure.size(); ++k) out << k << " " << k << "\n";
      out << "\n";
    }
  }
  const std::string db = (dir / "database.db").string();
  ASSERT_EQ(RunColmap("database_creator --database_path " + db, dir / "creator.log"), 0)
      << ReadLog(dir / "creator.log");
  ASSERT_EQ(RunColmap("feature_importer --database_path " + db + " --image_path " +
                          (dir / "images").string() + " --import_path " + (dir / "features").string() +
                          " --ImageReader.single_camera 1 --ImageReader.camera_model SIMPLE_PINHOLE"
                          " --ImageReader.camera_params 500,320,240",
                      dir / "importer.log"),
            0)
      << ReadLog(dir / "importer.log");
  ASSERT_EQ(RunColmap("matches_importer --database_path " + db + " --match_list_path " +
                          (dir / "matches.txt").string() +
                          " --match_type raw --SiftMatching.use_gpu 0 --SiftMatching.num_threads 1"
                          " --SiftMatching.compute_relative_pose 1",
                      dir / "matcher.log"),
            0)
      << ReadLog(dir / "matcher.log");

  const ColmapDatabase database = ReadColmapDatabase(db);
  ASSERT_EQ(database.sfm_data.views.size(), 3u);
  ASSERT_EQ(database.sfm_data.intrinsics.size(), 1u);
  EXPECT_EQ(database.sfm_data.intrinsics.begin()->second, scene.intrinsics.at(0));  // 320 - 0.5 = 319.5
  // COLMAP numbers images from 1 in name order; map them back to our views by file name.
  std::map<IndexT, IndexT> view_of_image;
  for (const auto& [image_id, view] : database.sfm_data.views) {
    for (const auto& [v, ours] : scene.views) {
      if (ours.filename == view.filename) view_of_image[image_id] = v;
    }
  }
  ASSERT_EQ(view_of_image.size(), 3u);
  for (const auto& [image_id, v] : view_of_image) {
    const FeatureSet& features = database.features.at(image_id);
    ASSERT_EQ(features.size(), scene.structure.size());
    for (const auto& [k, landmark] : scene.structure) {
      // Written in COLMAP's convention (+0.5), read back in ours; float and 9-digit text rounding.
      EXPECT_NEAR(features.keypoints[k].x, landmark.observations.at(v).x.x(), 1e-4);
      EXPECT_NEAR(features.keypoints[k].y, landmark.observations.at(v).x.y(), 1e-4);
      EXPECT_NEAR(features.keypoints[k].scale, 1.5 + 0.01 * k, 1e-6);
      EXPECT_NEAR(features.keypoints[k].orientation, 0.02 * k, 1e-6);
      EXPECT_EQ(features.descriptors[k], MakeDescriptor(k));
    }
  }
  EXPECT_EQ(database.putative.size(), 3u);
  ASSERT_EQ(database.verified.size(), 3u);
  for (const auto& [pair, geometry] : database.verified) {
    SCOPED_TRACE(std::to_string(pair.first) + "-" + std::to_string(pair.second));
    EXPECT_EQ(geometry.config, static_cast<int>(ColmapTwoViewConfig::kCalibrated));
    EXPECT_EQ(geometry.inliers.size(), scene.structure.size());
    // E is [t]x R of the relative pose first -> second (x_second^T E x_first = 0), up to scale
    // and sign. COLMAP 3.8's matches_importer leaves qvec/tvec zero even with
    // --SiftMatching.compute_relative_pose, so the reader reports no relative pose.
    EXPECT_FALSE(geometry.relative_pose.has_value());
    const RelativePose truth = RelativePoseBetween(scene.poses.at(view_of_image.at(pair.first)),
                                                   scene.poses.at(view_of_image.at(pair.second)));
    Eigen::Matrix3d t_cross;
    t_cross << 0, -truth.translation.z(), truth.translation.y(), truth.translation.z(), 0,
        -truth.translation.x(), -truth.translation.y(), truth.translation.x(), 0;
    const Eigen::Matrix3d expected = (t_cross * truth.rotation).normalized();
    const Eigen::Matrix3d actual = geometry.E.normalized();
    EXPECT_LT(std::min((actual - expected).norm(), (actual + expected).norm()), 1e-4);
  }
}

TEST(ColmapInterop, ColmapMapsADatabaseWeWrote) {
  REQUIRE_COLMAP();
  const SfmData scene = SyntheticScene();
  ColmapDatabase database;
  for (const auto& [v, view] : scene.views) {
    // COLMAP numbers images from 1; ours may start at 0, which its database also accepts.
    database.sfm_data.views[v] = view;
    FeatureSet& features = database.features[v];
    for (const auto& [k, landmark] : scene.structure) {
      const Eigen::Vector2d x = landmark.observations.at(v).x;
      features.keypoints.push_back({static_cast<float>(x.x()), static_cast<float>(x.y()), 1.f, 0.f});
    }
  }
  database.sfm_data.intrinsics = scene.intrinsics;
  for (const auto& [a, b] : {std::pair<IndexT, IndexT>{0, 1}, {0, 2}, {1, 2}}) {
    std::vector<FeatureMatch> matches;
    for (IndexT k = 0; k < scene.structure.size(); ++k) matches.push_back({k, k});
    database.putative[{a, b}] = matches;
    ColmapTwoViewGeometry geometry;
    geometry.inliers = matches;
    geometry.config = static_cast<int>(ColmapTwoViewConfig::kCalibrated);
    geometry.relative_pose = RelativePoseBetween(scene.poses.at(a), scene.poses.at(b));
    database.verified[{a, b}] = geometry;
  }
  const fs::path dir = testing::ScratchDir("interop_mapper");
  fs::create_directories(dir / "images");
  fs::create_directories(dir / "sparse");
  for (const auto& [v, view] : scene.views) WritePgm(dir / "images" / view.filename, 640, 480);
  WriteColmapDatabase(database, dir / "database.db");
  ASSERT_EQ(RunColmap("mapper --database_path " + (dir / "database.db").string() + " --image_path " +
                          (dir / "images").string() + " --output_path " + (dir / "sparse").string() +
                          " --Mapper.num_threads 1 --Mapper.ba_refine_focal_length 0"
                          " --Mapper.ba_refine_extra_params 0",
                      dir / "mapper.log"),
            0)
      << ReadLog(dir / "mapper.log");
  const SfmData model = ReadColmapModel(dir / "sparse" / "0");
  EXPECT_EQ(model.PosedViewIds().size(), 3u);
  EXPECT_GT(model.structure.size(), 50u);
  EXPECT_EQ(model.intrinsics.at(0), scene.intrinsics.at(0));
}

}  // namespace
}  // namespace sfm_pruning
