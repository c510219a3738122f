// COLMAP sparse models: the real temple models written by COLMAP 3.8 and 4.1.1, round trips,
// the points2D / id_feat mapping and error handling.
#include "sfm_pruning/io/colmap_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "sfm_pruning/util/error.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning {
namespace {
namespace fs = std::filesystem;

// Exact equality except rotations, which pass through a quaternion (a few ulp).
void ExpectSameModel(const SfmData& a, const SfmData& b, double tolerance = 0.0) {
  EXPECT_EQ(a.views, b.views);
  ASSERT_EQ(a.intrinsics.size(), b.intrinsics.size());
  for (const auto& [id, intrinsics] : a.intrinsics) {
    const CameraIntrinsics& other = b.intrinsics.at(id);
    ASSERT_EQ(intrinsics.model(), other.model());
    for (size_t k = 0; k < intrinsics.params().size(); ++k) {
      EXPECT_NEAR(intrinsics.params()[k], other.params()[k], tolerance * std::abs(other.params()[k]));
    }
  }
  ASSERT_EQ(a.poses.size(), b.poses.size());
  for (const auto& [id, pose] : a.poses) {
    EXPECT_LT((pose.rotation - b.poses.at(id).rotation).norm(), 1e-15 + tolerance);
    EXPECT_LT((pose.center - b.poses.at(id).center).norm(), 1e-14 * (1 + pose.center.norm()) + tolerance);
  }
  ASSERT_EQ(a.structure.size(), b.structure.size());
  for (const auto& [id, landmark] : a.structure) {
    const Landmark& other = b.structure.at(id);
    EXPECT_LE((landmark.X - other.X).norm(), tolerance * landmark.X.norm());
    EXPECT_EQ(landmark.observations, other.observations);
    EXPECT_EQ(landmark.color, other.color);
    EXPECT_NEAR(landmark.error, other.error, tolerance * std::abs(other.error));
  }
}

// Mean pixel residual (observed minus projected) over every observation of the model.
Eigen::Vector2d MeanResidual(const SfmData& data, double* rms) {
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  double squared = 0;
  size_t count = 0;
  for (const auto& [id, landmark] : data.structure) {
    for (const auto& [view_id, observation] : landmark.observations) {
      const View& view = data.views.at(view_id);
      const Eigen::Vector2d projected =
          data.IntrinsicsOf(view).Project(data.PoseOf(view).ToCamera(landmark.X));
      sum += observation.x - projected;
      squared += (observation.x - projected).squaredNorm();
      ++count;
    }
  }
  *rms = std::sqrt(squared / count);
  return sum / count;
}

struct RealModel {
  const char* folder;
  size_t registered;
};

TEST(ColmapModel, ReadsRealModelsInBothEncodings) {
  for (const RealModel& real : {RealModel{"colmap-3.8", 13}, RealModel{"colmap-4.1.1", 16}}) {
    SCOPED_TRACE(real.folder);
    PRUNESFM_REQUIRE_SHARED(std::string("formats/colmap/") + real.folder, dir);
    EXPECT_EQ(DetectColmapModelFormat(dir / "sparse_bin"), ColmapModelFormat::kBinary);
    EXPECT_EQ(DetectColmapModelFormat(dir / "sparse_txt"), ColmapModelFormat::kText);
    const SfmData binary = ReadColmapModel(dir / "sparse_bin");
    const SfmData text = ReadColmapModel(dir / "sparse_txt");
    EXPECT_EQ(binary.views.size(), real.registered);
    EXPECT_EQ(binary.PosedViewIds().size(), real.registered);
    EXPECT_GT(binary.structure.size(), 1000u);
    // COLMAP writes its text files with 17 significant digits, so both encodings agree exactly.
    ExpectSameModel(binary, text);

    ASSERT_EQ(binary.intrinsics.size(), 1u);
    const CameraIntrinsics& camera = binary.intrinsics.begin()->second;
    EXPECT_EQ(camera.model(), CameraModel::kPinholeFxFy);
    EXPECT_EQ(camera.width(), 640u);
    // The principal point was held fixed at the true 302.32, 246.87 (COLMAP convention).
    EXPECT_NEAR(camera.PrincipalPoint().x(), 302.32 - 0.5, 1e-12);
    EXPECT_NEAR(camera.PrincipalPoint().y(), 246.87 - 0.5, 1e-12);
    EXPECT_EQ(binary.views.begin()->second.filename.substr(0, 8), "templeSR");

    // Observations were shifted consistently with the principal point: residuals are unbiased.
    // Getting the sign wrong would leave a mean of one pixel, forgetting the shift half a pixel.
    double rms = 0;
    const Eigen::Vector2d mean = MeanResidual(binary, &rms);
    EXPECT_LT(mean.norm(), 0.05);
    EXPECT_LT(rms, 1.5);
  }
}

// Features holding each observation at its id_feat, so that writing keeps the point2D indices.
FeaturesPerView FeaturesFromObservations(const SfmData& data) {
  FeaturesPerView features;
  for (const auto& [id, landmark] : data.structure) {
    for (const auto& [view_id, observation] : landmark.observations) {
      std::vector<Keypoint>& keypoints = features[view_id].keypoints;
      if (keypoints.size() <= observation.id_feat) keypoints.resize(observation.id_feat + 1);
      keypoints[observation.id_feat].x = static_cast<float>(observation.x.x());
      keypoints[observation.id_feat].y = static_cast<float>(observation.x.y());
    }
  }
  return features;
}

TEST(ColmapModel, RoundTripsAreExact) {
  PRUNESFM_REQUIRE_SHARED("formats/colmap/colmap-4.1.1/sparse_bin", real);
  const SfmData original = ReadColmapModel(real);
  const FeaturesPerView features = FeaturesFromObservations(original);
  const fs::path dir = testing::ScratchDir("colmap_model_roundtrip");
  for (ColmapModelFormat format : {ColmapModelFormat::kBinary, ColmapModelFormat::kText}) {
    WriteColmapModel(original, dir / "model", format, &features);
    EXPECT_EQ(DetectColmapModelFormat(dir / "model"), format);
    const SfmData back = ReadColmapModel(dir / "model");
    ExpectSameModel(original, back);
    // Second generation: the written quaternions are stable.
    WriteColmapModel(back, dir / "model", format, &features);
    ExpectSameModel(back, ReadColmapModel(dir / "model"));
  }
}

// Three views (one without a pose), two landmarks, features for the posed views.
SfmData SmallScene(FeaturesPerView* features) {
  SfmData data;
  data.intrinsics[0] =
      CameraIntrinsics(CameraModel::kPinholeRadialK1, 400, 300, {350.25, 199.5, 149.5, -0.05});
  for (IndexT id : {0u, 1u, 2u}) {
    View view;
    view.id_view = id;
    view.id_pose = id;
    view.id_intrinsic = 0;
    view.local_path = id == 2 ? "sub" : "";
    view.filename = "img" + std::to_string(id) + ".png";
    view.width = 400;
    view.height = 300;
    data.views[id] = view;
  }
  data.poses[0] = Pose(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, 0));
  data.poses[2] = Pose(Eigen::AngleAxisd(0.3, Eigen::Vector3d(0.2, 1, 0.1).normalized()).toRotationMatrix(),
                       Eigen::Vector3d(1.5, -0.25, 0.125));
  for (IndexT id : {0u, 1u, 2u}) {
    FeatureSet& set = (*features)[id];
    for (int k = 0; k < 5; ++k) set.keypoints.push_back({10.25f * k, 20.5f + k, 1.f, 0.f});
  }
  Landmark a;
  a.X = {0.1, -0.2, 5.0};
  a.color = {200, 100, 50};
  a.error = 0.75;
  a.observations[0] = {{30.75, 23.5}, 3};
  a.observations[1] = {{11.0, 21.0}, 1};  // view 1 has no pose: dropped
  a.observations[2] = {{0.0, 20.5}, 0};
  Landmark b;  // seen only by the unposed view: dropped
  b.X = {1, 2, 3};
  b.observations[1] = {{41.0, 24.5}, 4};
  Landmark c;
  c.X = {-1, 0.5, 7};
  c.observations[2] = {{41.0, 24.5}, 4};
  data.structure[7] = a;
  data.structure[8] = b;
  data.structure[9] = c;
  return data;
}

TEST(ColmapModel, WithFeaturesPoint2DIndexIsFeatureIndex) {
  FeaturesPerView features;
  const SfmData data = SmallScene(&features);
  const fs::path dir = testing::ScratchDir("colmap_model_features");
  WriteColmapModel(data, dir, ColmapModelFormat::kText, &features);
  const SfmData back = ReadColmapModel(dir);
  EXPECT_EQ(back.views.size(), 2u);  // only posed views are written
  EXPECT_EQ(back.views.at(2).RelativeImagePath(), "sub/img2.png");
  ASSERT_EQ(back.structure.size(), 2u);
  EXPECT_EQ(back.structure.count(8), 0u);
  const Landmark& a = back.structure.at(7);
  ASSERT_EQ(a.observations.size(), 2u);
  EXPECT_EQ(a.observations.at(0), data.structure.at(7).observations.at(0));
  EXPECT_EQ(a.observations.at(2), data.structure.at(7).observations.at(2));
  EXPECT_EQ(a.color, (std::array<uint8_t, 3>{200, 100, 50}));
  EXPECT_EQ(a.error, 0.75);
  EXPECT_EQ(back.structure.at(9).observations.at(2).id_feat, 4u);
  EXPECT_EQ(back.intrinsics.at(0), data.intrinsics.at(0));
  EXPECT_LT((back.poses.at(2).rotation - data.poses.at(2).rotation).norm(), 1e-15);

  // Unobserved keypoints are listed too, shifted to COLMAP's convention.
  std::ifstream images(dir / "images.txt");
  std::string line, points_of_view0;
  while (std::getline(images, line)) {
    if (line.rfind("0 ", 0) == 0) std::getline(images, points_of_view0);
  }
  EXPECT_EQ(points_of_view0.substr(0, 18), "0.5 21 -1 10.75 22");
}

TEST(ColmapModel, WithoutFeaturesObservationsAreCompact) {
  FeaturesPerView features;
  const SfmData data = SmallScene(&features);
  const fs::path dir = testing::ScratchDir("colmap_model_compact");
  WriteColmapModel(data, dir, ColmapModelFormat::kBinary);
  const SfmData back = ReadColmapModel(dir);
  // View 2 sees landmarks 7 and 9, listed in landmark order: point2D 0 and 1.
  EXPECT_EQ(back.structure.at(7).observations.at(2).id_feat, 0u);
  EXPECT_EQ(back.structure.at(9).observations.at(2).id_feat, 1u);
  EXPECT_EQ(back.structure.at(9).observations.at(2).x, Eigen::Vector2d(41.0, 24.5));
}

TEST(ColmapModel, RejectsBadInput) {
  const fs::path dir = testing::ScratchDir("colmap_model_errors");
  EXPECT_THROW(ReadColmapModel(dir / "missing"), Error);
  EXPECT_THROW(ReadColmapModel(dir), Error);  // empty folder

  FeaturesPerView features;
  const SfmData data = SmallScene(&features);
  WriteColmapModel(data, dir / "bin", ColmapModelFormat::kBinary);
  const std::string images = (dir / "bin" / "images.bin").string();
  fs::resize_file(images, fs::file_size(images) - 3);
  try {
    ReadColmapModel(dir / "bin");
    ADD_FAILURE() << "truncated images.bin accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("images.bin: truncated"), std::string::npos) << e.what();
  }

  WriteColmapModel(data, dir / "txt", ColmapModelFormat::kText);
  std::ofstream(dir / "txt" / "points3D.txt") << "1 0 0 1 255 255 255 0.5 3 0\n";
  WriteColmapModel(SfmData{data.root_path, data.views, data.intrinsics, data.poses, {}, {}}, dir / "txt",
                   ColmapModelFormat::kText);  // images.txt without observations
  std::ofstream(dir / "txt" / "points3D.txt") << "1 0 0 1 255 255 255 0.5 3 0\n";
  try {
    ReadColmapModel(dir / "txt");
    ADD_FAILURE() << "track to a missing image accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("points3D.txt: point3D 1 observes missing point2D 0 of image 3"),
              std::string::npos)
        << e.what();
  }
  std::ofstream(dir / "txt" / "cameras.txt") << "0 FOV 400 300 350 200 150 0.9\n";
  EXPECT_THROW(ReadColmapModel(dir / "txt"), Error);

  // Records the text files cannot hold: a cut-short file, a repeated id, a reference to nothing,
  // an impossible camera.
  const auto expect_error = [&](const fs::path& model, const std::string& text) {
    try {
      ReadColmapModel(model);
      ADD_FAILURE() << "accepted; expected an error mentioning " << text;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    }
  };
  const auto text_model = [&](const std::string& name) {
    WriteColmapModel(data, dir / name, ColmapModelFormat::kText);
    EXPECT_NO_THROW(ReadColmapModel(dir / name));
    return dir / name;
  };
  const auto rewrite = [](const fs::path& file, const std::function<void(std::vector<std::string>*)>& edit) {
    std::vector<std::string> lines;
    std::ifstream in(file);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    in.close();
    edit(&lines);
    std::ofstream out(file);
    for (const std::string& line : lines) out << line << "\n";
  };
  const auto first_data_line = [](std::vector<std::string>* lines) -> std::string& {
    for (std::string& line : *lines) {
      if (!line.empty() && line[0] != '#') return line;
    }
    throw std::runtime_error("no data line");
  };
  const fs::path truncated = text_model("truncated");
  rewrite(truncated / "points3D.txt", [](std::vector<std::string>* lines) { lines->pop_back(); });
  expect_error(truncated, "points3D.txt: the header declares");
  const fs::path duplicate = text_model("duplicate");
  rewrite(duplicate / "cameras.txt", [&](std::vector<std::string>* lines) { lines->push_back(first_data_line(lines)); });
  expect_error(duplicate, "duplicate CAMERA_ID");
  const fs::path missing_point = text_model("missing_point");
  rewrite(missing_point / "images.txt", [](std::vector<std::string>* lines) {
    int data_lines = 0;
    for (std::string& line : *lines) {
      if (!line.empty() && line[0] == '#') continue;
      if (++data_lines == 2) line = "10 20 999999";  // the first image's POINTS2D line
    }
  });
  expect_error(missing_point, "names 3D point 999999, which is not in points3D.txt");
  const fs::path empty_camera = text_model("empty_camera");
  rewrite(empty_camera / "cameras.txt", [&](std::vector<std::string>* lines) {
    std::string& line = first_data_line(lines);
    std::istringstream tokens(line);
    std::string id, model, width;
    tokens >> id >> model >> width;
    line = id + " " + model + " 0" + line.substr(static_cast<size_t>(tokens.tellg()));
  });
  expect_error(empty_camera, "image size 0x");

  FeaturesPerView too_few = features;
  too_few[2].keypoints.resize(2);
  EXPECT_THROW(WriteColmapModel(data, dir / "bad", ColmapModelFormat::kBinary, &too_few), Error);
  EXPECT_FALSE(fs::exists(dir / "bad"));
}

}  // namespace
}  // namespace sfm_pruning
