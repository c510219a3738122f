// sfm_data.json / .bin: exact round trips and robustness against damaged files.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <random>
#include <string>

#include "sfm_pruning/io/openmvg_sfm_data.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning {
namespace {

namespace fs = std::filesystem;

// A scene with awkward values: several camera models, view priors (enabled and disabled),
// undefined ids, doubles that need all 17 digits, extremes and subnormals. Seeded.
SfmData AwkwardScene(bool with_nan) {
  std::mt19937 rng(20240607);
  std::uniform_real_distribution<double> uniform(-1000.0, 1000.0);
  SfmData data;
  data.root_path = "relative/images with space/ünïcode";
  const CameraModel models[] = {CameraModel::kPinhole,         CameraModel::kPinholeRadialK1,
                                CameraModel::kPinholeRadialK3, CameraModel::kPinholeBrownT2,
                                CameraModel::kFisheye,         CameraModel::kSpherical};
  IndexT intrinsic_id = 3;
  for (CameraModel model : models) {
    std::vector<double> params(NumCameraParams(model));
    for (double& p : params) p = uniform(rng) / 3.0;
    if (!params.empty()) params[0] = std::abs(params[0]) + 1.0;  // a focal length is positive
    data.intrinsics[intrinsic_id] = CameraIntrinsics(model, 1000 + intrinsic_id, 700, params);
    intrinsic_id += 10;
  }
  IndexT view_id = 100;
  for (const auto& [id, intrinsic] : data.intrinsics) {
    for (int k = 0; k < 2; ++k, view_id += 7) {
      View view;
      view.id_view = view_id;
      view.id_intrinsic = id;
      view.id_pose = view_id * 2;
      view.filename = "image_" + std::to_string(view_id) + ".png";
      view.local_path = k == 0 ? "" : "sub\"dir";  // a quote must survive escaping
      view.width = intrinsic.width();
      view.height = intrinsic.height();
      if (view_id % 3 == 0)
        view.center_prior = PoseCenterPrior{{uniform(rng), 1e-300, 1e300}, {1.0, 0.5, 0.25}};
      if (view_id % 3 == 1) view.has_prior_record = true;
      data.views[view_id] = view;
      const Eigen::Matrix3d R =
          Eigen::AngleAxisd(uniform(rng), Eigen::Vector3d(uniform(rng), uniform(rng), 1.0).normalized())
              .toRotationMatrix();
      data.poses[view.id_pose] =
          Pose(R, {uniform(rng), 1.0 / 3.0, std::numeric_limits<double>::denorm_min()});
    }
  }
  View unknown;
  unknown.id_view = 9999;
  unknown.filename = "unknown.jpg";
  data.views[9999] = unknown;  // UndefinedIndexT intrinsic and pose

  for (IndexT track = 0; track < 40; ++track) {
    Landmark& landmark = data.structure[track * 3 + 1];
    landmark.X = {uniform(rng), uniform(rng), uniform(rng) * 1e-12};
    for (const auto& [id, view] : data.views) {
      if ((id + track) % 4 != 0) continue;
      Observation observation;
      observation.id_feat = (track * 131 + id) % 5000;
      observation.x = {uniform(rng) + 1000.0, uniform(rng) + 1000.0};
      landmark.observations[id] = observation;
    }
  }
  data.control_points[7].X = {0.1, 0.2, 0.3};
  data.control_points[7].observations[100].x = {1.5, 2.5};
  if (with_nan) data.structure[1].X.y() = std::nan("");
  return data;
}

void ExpectExactRoundTrip(const std::string& file_name) {
  const fs::path dir = testing::ScratchDir("openmvg_sfm_data_roundtrip_" + file_name);
  const SfmData original = AwkwardScene(/*with_nan=*/false);
  WriteSfmData(original, dir / file_name);
  const SfmData back = ReadSfmData(dir / file_name);
  EXPECT_TRUE(back == original);
  EXPECT_EQ(back.views, original.views);
  EXPECT_EQ(back.intrinsics, original.intrinsics);
  EXPECT_EQ(back.structure, original.structure);
  // Writing what was read gives the same bytes.
  const fs::path again = dir / ("again_" + file_name);
  WriteSfmData(back, again);
  EXPECT_EQ(ReadFileToString(dir / file_name), ReadFileToString(again));
}

TEST(OpenMvgSfmDataRoundTrip, JsonIsExact) { ExpectExactRoundTrip("sfm_data.json"); }
TEST(OpenMvgSfmDataRoundTrip, BinaryIsExact) { ExpectExactRoundTrip("sfm_data.bin"); }

TEST(OpenMvgSfmDataRoundTrip, NanIsRefusedOnReadingInBothFormats) {
  const fs::path dir = testing::ScratchDir("openmvg_sfm_data_roundtrip_nan");
  const SfmData original = AwkwardScene(/*with_nan=*/true);
  for (const char* name : {"sfm_data.json", "sfm_data.bin"}) {
    WriteSfmData(original, dir / name);
    try {
      ReadSfmData(dir / name);
      ADD_FAILURE() << name << ": a NaN landmark was accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(": landmark 1: the position is not finite"), std::string::npos) << e.what();
    }
  }
}

TEST(OpenMvgSfmDataRoundTrip, BinaryHonoursRequestedParts) {
  const fs::path path = testing::ScratchDir("openmvg_sfm_data_bin_parts") / "sfm_data.bin";
  const SfmData original = AwkwardScene(false);
  WriteSfmData(original, path, SfmDataParts::kViews | SfmDataParts::kExtrinsics);
  // Read as written: asking for the intrinsics too would find views naming intrinsics the file
  // does not hold, which OpenMVG refuses as well.
  EXPECT_THROW(ReadSfmData(path), Error);
  const SfmData back = ReadSfmData(path, SfmDataParts::kViews | SfmDataParts::kExtrinsics);
  EXPECT_EQ(back.views, original.views);
  EXPECT_TRUE(back.intrinsics.empty());
  EXPECT_EQ(back.poses.size(), original.poses.size());
  EXPECT_TRUE(back.structure.empty());
  const SfmData views_only = ReadSfmData(path, SfmDataParts::kViews);
  EXPECT_TRUE(views_only.poses.empty());
  EXPECT_EQ(views_only.views.size(), original.views.size());
}

TEST(OpenMvgSfmDataRoundTrip, PinholeFxFyTravelsInJsonButNotInBinary) {
  SfmData data;
  View view;
  view.id_view = 0;
  view.id_intrinsic = 0;
  data.views[0] = view;
  data.intrinsics[0] = CameraIntrinsics(CameraModel::kPinholeFxFy, 640, 480, {500.0, 510.5, 320.0, 240.0});
  const fs::path dir = testing::ScratchDir("openmvg_sfm_data_fxfy");
  WriteSfmData(data, dir / "sfm_data.json");
  EXPECT_TRUE(ReadSfmData(dir / "sfm_data.json") == data);
  const std::string text = ReadFileToString(dir / "sfm_data.json");
  EXPECT_NE(text.find("\"polymorphic_name\": \"pinhole\""), std::string::npos);
  EXPECT_NE(text.find("\"focal_length_y\": 510.5"), std::string::npos);
  EXPECT_THROW(WriteSfmData(data, dir / "sfm_data.bin"), Error);
  EXPECT_FALSE(fs::exists(dir / "sfm_data.bin"));  // nothing half-written
  EXPECT_TRUE(fs::is_empty(dir) || fs::exists(dir / "sfm_data.json"));
}

// Reads `bytes` as a file; passes when it loads or throws Error, fails on anything else.
void ExpectLoadsOrThrowsError(const fs::path& path, const std::string& bytes, const std::string& what) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
  try {
    ReadSfmData(path);
  } catch (const Error&) {
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << ": unexpected exception " << e.what();
  }
}

void DamageAndReload(const std::string& file_name) {
  const fs::path dir = testing::ScratchDir("openmvg_sfm_data_damage_" + file_name);
  SfmData scene = AwkwardScene(false);
  scene.structure.erase(scene.structure.begin(), std::next(scene.structure.begin(), 35));  // keep it small
  WriteSfmData(scene, dir / file_name);
  const std::string good = ReadFileToString(dir / file_name);
  const fs::path damaged = dir / ("damaged_" + file_name);
  int truncations_rejected = 0;
  const size_t step = std::max<size_t>(1, good.size() / 300);
  for (size_t size = 0; size < good.size(); size += step) {
    std::ofstream(damaged, std::ios::binary | std::ios::trunc) << good.substr(0, size);
    try {
      ReadSfmData(damaged);
    } catch (const Error&) {
      ++truncations_rejected;
    }
  }
  EXPECT_EQ(truncations_rejected,
            static_cast<int>((good.size() + step - 1) / step));  // every cut is detected
  std::mt19937 rng(7);
  std::uniform_int_distribution<size_t> position(0, good.size() - 1);
  std::uniform_int_distribution<int> byte(0, 255);
  for (int trial = 0; trial < 300; ++trial) {
    std::string bytes = good;
    for (int flips = 0; flips <= trial % 3; ++flips) bytes[position(rng)] = static_cast<char>(byte(rng));
    ExpectLoadsOrThrowsError(damaged, bytes, "trial " + std::to_string(trial));
  }
}

TEST(OpenMvgSfmDataRobustness, DamagedJsonNeverCrashes) { DamageAndReload("sfm_data.json"); }
TEST(OpenMvgSfmDataRobustness, DamagedBinaryNeverCrashes) { DamageAndReload("sfm_data.bin"); }

TEST(OpenMvgSfmDataRobustness, BinaryErrorsNameTheFile) {
  const fs::path path = testing::ScratchDir("openmvg_sfm_data_bin_errors") / "sfm_data.bin";
  WriteSfmData(AwkwardScene(false), path);
  const std::string good = ReadFileToString(path);
  std::ofstream(path, std::ios::binary | std::ios::trunc) << good.substr(0, 100);
  try {
    ReadSfmData(path);
    FAIL() << "truncated file accepted";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(path.string() + ": truncated file", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos);
  }
}

}  // namespace
}  // namespace sfm_pruning
