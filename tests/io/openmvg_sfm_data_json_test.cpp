// sfm_data.json against hand-made golden files (tests/data/openmvg_json), legacy variants and
// malformed input.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "sfm_pruning/io/openmvg_sfm_data.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning {
namespace {

namespace fs = std::filesystem;

fs::path GoldenFile(const std::string& name) { return testing::TestDataDir() / "openmvg_json" / name; }

Eigen::Matrix3d RotationZ90() { return (Eigen::Matrix3d() << 0, -1, 0, 1, 0, 0, 0, 0, 1).finished(); }
Eigen::Matrix3d RotationX90() { return (Eigen::Matrix3d() << 1, 0, 0, 0, 0, 1, 0, -1, 0).finished(); }

View MakeView(IndexT id, const std::string& filename, uint32_t width, uint32_t height, IndexT intrinsic,
              IndexT pose) {
  View view;
  view.id_view = id;
  view.filename = filename;
  view.width = width;
  view.height = height;
  view.id_intrinsic = intrinsic;
  view.id_pose = pose;
  return view;
}

Observation MakeObservation(IndexT feature, double x, double y) {
  Observation observation;
  observation.id_feat = feature;
  observation.x = {x, y};
  return observation;
}

// The content of all_types.json, written out independently of the reader.
SfmData AllTypesScene() {
  SfmData data;
  data.root_path = "/data/scene/images";
  data.views[0] = MakeView(0, "img_000.jpg", 3072, 2048, 0, 0);
  data.views[1] = MakeView(1, "img_001.jpg", 3072, 2048, 1, 1);
  data.views[1].center_prior = PoseCenterPrior{{10.5, -2.25, 100.0}, {1.0, 1.0, 2.5}};
  data.views[2] = MakeView(2, "img_002.jpg", 3000, 2000, 2, 2);
  data.views[2].local_path = "sub";
  data.views[3] = MakeView(3, "img_003.jpg", 1920, 1080, 3, 3);
  data.views[3].has_prior_record = true;
  data.views[4] = MakeView(4, "img_004.jpg", 1280, 960, 4, 4);
  data.views[5] = MakeView(5, "pano_005.jpg", 4000, 2000, 5, 5);
  data.views[6] = MakeView(6, "img_006.jpg", 3000, 2000, 6, kUndefinedIndex);
  data.views[6].center_prior = PoseCenterPrior{{-1.0, 0.0, 3.75}, {0.5, 0.5, 0.5}};
  data.views[7] = MakeView(7, "img_007.jpg", 640, 480, 7, 7);
  data.views[8] = MakeView(8, "img_008.jpg", 640, 480, kUndefinedIndex, kUndefinedIndex);

  data.intrinsics[0] = CameraIntrinsics(CameraModel::kPinhole, 3072, 2048, {2760.0, 1536.0, 1024.0});
  data.intrinsics[1] =
      CameraIntrinsics(CameraModel::kPinholeRadialK1, 3072, 2048, {2800.5, 1535.5, 1023.25, -0.125});
  data.intrinsics[2] = CameraIntrinsics(CameraModel::kPinholeRadialK3, 3000, 2000,
                                        {2500.0, 1500.0, 1000.0, 0.01, -0.002, 0.0003});
  data.intrinsics[3] = CameraIntrinsics(CameraModel::kPinholeBrownT2, 1920, 1080,
                                        {1500.0, 960.0, 540.0, 0.1, -0.05, 0.001, 0.0002, -0.0004});
  data.intrinsics[4] =
      CameraIntrinsics(CameraModel::kFisheye, 1280, 960, {600.0, 640.0, 480.0, 0.02, -0.01, 0.005, -0.001});
  data.intrinsics[5] = CameraIntrinsics(CameraModel::kSpherical, 4000, 2000, {});
  data.intrinsics[6] =
      CameraIntrinsics(CameraModel::kPinholeRadialK3, 3000, 2000, {2450.0, 1499.5, 999.5, 0.0, 0.0, 0.0});
  data.intrinsics[7] = CameraIntrinsics(CameraModel::kPinholeFxFy, 640, 480, {500.0, 520.0, 320.0, 240.0});

  data.poses[0] = Pose(Eigen::Matrix3d::Identity(), {0.0, 0.0, 0.0});
  data.poses[1] = Pose(RotationZ90(), {1.0, 0.0, 0.0});
  data.poses[2] = Pose(RotationX90(), {0.5, -0.25, 2.0});
  data.poses[3] = Pose(Eigen::Matrix3d::Identity(), {2.0, 0.0, 0.0});
  data.poses[4] = Pose(RotationZ90(), {3.0, 1.5, -0.5});
  data.poses[5] = Pose(Eigen::Matrix3d::Identity(), {0.0, 0.0, 4.0});
  data.poses[7] = Pose(RotationX90(), {-1.0, -2.0, -3.0});

  data.structure[0].X = {0.5, 0.125, 5.0};
  data.structure[0].observations = {{0, MakeObservation(12, 1812.0, 1079.25)},
                                    {1, MakeObservation(7, 977.5, 1080.0)}};
  data.structure[5].X = {-1.5, 2.0, 8.0};
  data.structure[5].observations = {{2, MakeObservation(0, 100.5, 200.25)},
                                    {4, MakeObservation(3, 50.0, 60.0)},
                                    {7, MakeObservation(42, 1.0, 2.0)}};
  data.structure[17].X = {3.0, -4.0, 12.5};
  data.control_points[0].X = {10.0, 20.0, 30.0};
  data.control_points[0].observations = {{0, MakeObservation(0, 300.5, 400.5)},
                                         {3, MakeObservation(0, 10.0, 11.0)}};
  return data;
}

void WriteText(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// The error message ReadSfmData gives for `json`, or "" when it loads.
std::string ReadError(const std::string& json, const std::string& name = "bad.json") {
  const fs::path path = testing::ScratchDir("openmvg_sfm_data_errors_" + name) / name;
  WriteText(path, json);
  try {
    ReadSfmData(path);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(OpenMvgSfmDataJson, GoldenFileReadsToTheExpectedScene) {
  const SfmData data = ReadSfmData(GoldenFile("all_types.json"));
  const SfmData expected = AllTypesScene();
  EXPECT_EQ(data.root_path, expected.root_path);
  EXPECT_EQ(data.views, expected.views);
  EXPECT_EQ(data.intrinsics, expected.intrinsics);
  EXPECT_EQ(data.structure, expected.structure);
  EXPECT_EQ(data.control_points, expected.control_points);
  EXPECT_TRUE(data == expected);
  // Spot checks of the trickier mappings.
  EXPECT_EQ(data.views.at(8).id_intrinsic, 4294967295u);
  EXPECT_FALSE(data.views.at(3).center_prior.has_value());
  EXPECT_TRUE(data.views.at(3).has_prior_record);
  EXPECT_EQ(data.views.at(1).center_prior->weight, Eigen::Vector3d(1.0, 1.0, 2.5));
  EXPECT_EQ(data.intrinsics.at(7).model(), CameraModel::kPinholeFxFy);
  EXPECT_EQ(data.intrinsics.at(7).FocalY(), 520.0);
  EXPECT_EQ(data.intrinsics.at(5).width(), 4000u);
  EXPECT_EQ(data.poses.at(1).rotation(0, 1), -1.0);  // rows are stored row by row
  EXPECT_EQ(data.PosedViewIds().size(), 7u);
}

TEST(OpenMvgSfmDataJson, WriterReproducesTheGoldenFileByteForByte) {
  const fs::path path = testing::ScratchDir("openmvg_sfm_data_golden") / "sfm_data.json";
  WriteSfmData(AllTypesScene(), path);
  EXPECT_EQ(ReadFileToString(path), ReadFileToString(GoldenFile("all_types.json")));
}

TEST(OpenMvgSfmDataJson, WritesOnlyTheRequestedPartsAndReadsOnlyTheRequestedParts) {
  const fs::path path = testing::ScratchDir("openmvg_sfm_data_parts") / "sfm_data.json";
  WriteSfmData(AllTypesScene(), path, SfmDataParts::kViews | SfmDataParts::kIntrinsics);
  const std::string text = ReadFileToString(path);
  EXPECT_NE(text.find("\"extrinsics\": [],"), std::string::npos);
  EXPECT_NE(text.find("\"structure\": [],"), std::string::npos);
  EXPECT_NE(text.find("\"control_points\": []\n}"), std::string::npos);
  const SfmData back = ReadSfmData(path);
  EXPECT_EQ(back.views, AllTypesScene().views);
  EXPECT_EQ(back.intrinsics, AllTypesScene().intrinsics);
  EXPECT_TRUE(back.poses.empty());

  const SfmData only_structure = ReadSfmData(GoldenFile("all_types.json"), SfmDataParts::kStructure);
  EXPECT_TRUE(only_structure.views.empty());
  EXPECT_TRUE(only_structure.intrinsics.empty());
  EXPECT_EQ(only_structure.structure, AllTypesScene().structure);
}

TEST(OpenMvgSfmDataJson, UnrequestedSectionsMayBeMissingOrGarbage) {
  const std::string json =
      R"({"sfm_data_version": "0.3", "root_path": "", "views": [], "intrinsics": 17,
          "structure": "not read"})";
  const fs::path path = testing::ScratchDir("openmvg_sfm_data_unrequested") / "sfm_data.json";
  WriteText(path, json);
  EXPECT_TRUE(ReadSfmData(path, SfmDataParts::kViews).views.empty());
  EXPECT_THROW(ReadSfmData(path, SfmDataParts::kViews | SfmDataParts::kIntrinsics), Error);
}

TEST(OpenMvgSfmDataJson, ReadsVersion02WithLegacyValue0Intrinsics) {
  const SfmData data = ReadSfmData(GoldenFile("legacy_v02_value0.json"));
  ASSERT_EQ(data.views.size(), 2u);
  EXPECT_EQ(data.views.at(0).filename, "a.jpg");
  EXPECT_FALSE(data.views.at(0).has_prior_record);
  ASSERT_EQ(data.intrinsics.size(), 2u);
  EXPECT_EQ(data.intrinsics.at(0),
            CameraIntrinsics(CameraModel::kPinholeBrownT2, 1920, 1080,
                             {1500.0, 960.0, 540.0, 0.1, -0.05, 0.001, 0.0002, -0.0004}));
  EXPECT_EQ(data.intrinsics.at(1), CameraIntrinsics(CameraModel::kFisheye, 1280, 960,
                                                    {600.0, 640.0, 480.0, 0.02, -0.01, 0.005, -0.001}));
  ASSERT_EQ(data.control_points.size(), 1u);
  EXPECT_EQ(data.control_points.at(3).X, Eigen::Vector3d(1.0, 2.0, 3.0));
  // Written back, the legacy nesting is gone and the file reads to the same scene.
  const fs::path path = testing::ScratchDir("openmvg_sfm_data_legacy") / "sfm_data.json";
  WriteSfmData(data, path);
  EXPECT_EQ(ReadFileToString(path).find("value0"), std::string::npos);
  EXPECT_TRUE(ReadSfmData(path) == data);
}

TEST(OpenMvgSfmDataJson, ReadsVersion01WithoutControlPoints) {
  const SfmData data = ReadSfmData(GoldenFile("legacy_v01.json"));
  EXPECT_EQ(data.views.size(), 1u);
  EXPECT_EQ(data.intrinsics.at(0).FocalLength(), 500.0);  // integer literal in a double field
  EXPECT_EQ(data.structure.at(9).observations.at(0).id_feat, 5u);
  EXPECT_TRUE(data.control_points.empty());
}

TEST(OpenMvgSfmDataJson, ReadsReorderedKeysUnknownFieldsAndNonFiniteTokens) {
  const SfmData data = ReadSfmData(GoldenFile("reordered_extra_fields.json"),
                                   SfmDataParts::kViews | SfmDataParts::kIntrinsics | SfmDataParts::kExtrinsics);
  EXPECT_EQ(data.root_path, "/somewhere");
  ASSERT_EQ(data.views.size(), 2u);
  EXPECT_EQ(data.views.at(1).RelativeImagePath(), "x/y/v1.png");
  ASSERT_TRUE(data.views.at(0).center_prior.has_value());
  EXPECT_EQ(data.views.at(0).center_prior->center, Eigen::Vector3d(7.0, 8.0, 9.0));
  EXPECT_EQ(data.views.at(0).center_prior->weight, Eigen::Vector3d(1.0, 2.0, 3.0));
  EXPECT_EQ(data.intrinsics.at(7),
            CameraIntrinsics(CameraModel::kPinholeRadialK1, 100, 80, {90.0, 50.0, 40.0, 0.5}));
  EXPECT_EQ(data.poses.at(1).center, Eigen::Vector3d(1.0, 2.0, 3.0));
  // Landmark 4 holds NaN and -Infinity tokens: they parse as numbers (the error is not about
  // the JSON), and a landmark that is nowhere is refused.
  EXPECT_NE(ReadError(ReadFileToString(GoldenFile("reordered_extra_fields.json")))
                .find("bad.json: landmark 4: the position is not finite"),
            std::string::npos);
}

TEST(OpenMvgSfmDataJson, WritesNonFiniteValuesAsCerealDoes) {
  SfmData data;
  data.structure[0].X = {std::nan(""), std::numeric_limits<double>::infinity(), -1.0};
  const fs::path path = testing::ScratchDir("openmvg_sfm_data_nan") / "sfm_data.json";
  WriteSfmData(data, path);
  const std::string text = ReadFileToString(path);
  EXPECT_NE(text.find("NaN,"), std::string::npos);
  EXPECT_NE(text.find("Infinity,"), std::string::npos);
  EXPECT_THROW(ReadSfmData(path), Error);  // written as cereal would, refused on reading
}

TEST(OpenMvgSfmDataJson, ResolvesRepeatedSharedPointers) {
  // cereal writes a pointer it has already written as {"id": m} without data.
  const std::string json = R"({"sfm_data_version": "0.3", "root_path": "", "views": [
      {"key": 0, "value": {"polymorphic_id": 1073741824, "ptr_wrapper": {"id": 2147483649, "data": {
          "local_path": "", "filename": "a.jpg", "width": 4, "height": 3, "id_view": 0, "id_intrinsic": 0,
          "id_pose": 0}}}},
      {"key": 1, "value": {"polymorphic_id": 1073741824, "ptr_wrapper": {"id": 2147483650, "data": {
          "local_path": "", "filename": "b.jpg", "width": 4, "height": 3, "id_view": 1, "id_intrinsic": 1,
          "id_pose": 1}}}}],
    "intrinsics": [
      {"key": 0, "value": {"polymorphic_id": 2147483649, "polymorphic_name": "pinhole",
          "ptr_wrapper": {"id": 2147483651, "data": {"width": 4, "height": 3, "focal_length": 5.0,
          "principal_point": [2.0, 1.5]}}}},
      {"key": 1, "value": {"polymorphic_id": 1, "ptr_wrapper": {"id": 3}}}],
    "extrinsics": [], "structure": [], "control_points": []})";
  const fs::path path = testing::ScratchDir("openmvg_sfm_data_shared_pointer") / "sfm_data.json";
  WriteText(path, json);
  const SfmData data = ReadSfmData(path);
  ASSERT_EQ(data.intrinsics.size(), 2u);
  EXPECT_EQ(data.intrinsics.at(1), CameraIntrinsics::Pinhole(4, 3, 5.0, 2.0, 1.5));
}

TEST(OpenMvgSfmDataJson, ErrorsNameTheFileAndTheProblem) {
  EXPECT_NE(std::string(ReadError("")).find("bad.json: invalid or truncated JSON at byte 0"),
            std::string::npos);
  const std::string golden = ReadFileToString(GoldenFile("all_types.json"));
  EXPECT_NE(ReadError(golden.substr(0, 1000)).find("at byte 1000"), std::string::npos);

  // Each case damages the golden file in one place: {text to find, replacement, expected message}.
  const std::string observation_7 =
      ",\n                        \"value\": {\n                            \"id_feat\": 42";
  const struct {
    std::string from, to, message;
  } cases[] = {
      {"\"width\": 1920,", "\"width\": 1920.0,",
       "bad.json: views[3].value.ptr_wrapper.data.width: expected unsigned integer"},
      {"\"polymorphic_name\": \"fisheye\"", "\"polymorphic_name\": \"fancy_cam\"",
       "bad.json: intrinsics[4].value: unknown camera model \"fancy_cam\""},
      {"\"focal_length\": 2760.0,", "",
       "bad.json: intrinsics[0].value.ptr_wrapper.data: missing field \"focal_length\""},
      {"-0.125", "-0.125, 3.0",
       "bad.json: intrinsics[1].value.ptr_wrapper.data.disto_k1: expected 1 numbers, got 2"},
      {"\"key\": 7" + observation_7, "\"key\": 70" + observation_7,
       "bad.json: landmark 5 is observed in view 70, which does not exist"},
      {"\"id_pose\": 7", "\"id_pose\": 8", "bad.json: pose 7 is used by no view"},
      {"\"polymorphic_id\": 4,", "\"polymorphic_id\": 9,",
       "bad.json: intrinsics[6].value.polymorphic_id: polymorphic id 9 names no earlier type"},
      {"\"id\": 2147483650,", "\"id\": 5,",
       "bad.json: views[1].value.ptr_wrapper.id: pointer id 5 refers to no earlier object"},
  };
  for (const auto& c : cases) {
    std::string text = golden;
    const size_t at = text.find(c.from);
    ASSERT_NE(at, std::string::npos) << c.from;
    const std::string error = ReadError(text.replace(at, c.from.size(), c.to));
    EXPECT_NE(error.find(c.message), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;  // one line
  }
  EXPECT_NE(ReadError("{\"root_path\": \"\"}").find("missing field \"sfm_data_version\""), std::string::npos);
  EXPECT_NE(ReadError("[1, 2]").find("expected a JSON object"), std::string::npos);
  EXPECT_NE(ReadError("{}", "scene.xml").find("unsupported sfm_data extension"), std::string::npos);

  try {
    ReadSfmData("/nonexistent/sfm_data.json");
    FAIL() << "no error for a missing file";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent/sfm_data.json: file not found");
  }
}

}  // namespace
}  // namespace sfm_pruning
