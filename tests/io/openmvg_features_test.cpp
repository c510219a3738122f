// OpenMVG .feat / .desc / image_describer.json: hand-made golden files, exact round trips, bad
// input, and the real OpenMVG 2.1 Sceaux Castle project.
#include "sfm_pruning/io/openmvg_features.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "openmvg_features_test_support.hpp"
#include "sfm_pruning/io/openmvg_sfm_data.hpp"
#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning::openmvg_features_test {
namespace {
namespace fs = std::filesystem;

TEST(OpenMvgFeat, ReadsScaleOrientationLinesAndRewritesThemByteForByte) {
  const std::vector<Keypoint> keypoints = ReadFeatFile(Golden("sift.feat"));
  ASSERT_EQ(keypoints.size(), 3u);
  EXPECT_EQ(keypoints[0].x, 10.5f);
  EXPECT_EQ(keypoints[0].y, 20.25f);
  EXPECT_EQ(keypoints[0].scale, 1.5f);
  EXPECT_EQ(keypoints[0].orientation, 0.785398f);
  EXPECT_EQ(keypoints[2].x, 639.75f);
  EXPECT_EQ(keypoints[2].scale, 12.3457f);
  EXPECT_EQ(keypoints[2].orientation, 6.28318f);
  const fs::path out = testing::ScratchDir("feat_golden") / "sift.feat";
  WriteFeatFile(out, keypoints);
  EXPECT_EQ(ReadFileToString(out), ReadFileToString(Golden("sift.feat")));
}

TEST(OpenMvgFeat, ReadsPointAndAffineLayouts) {
  const std::vector<Keypoint> points = ReadFeatFile(Golden("point.feat"));
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[1].x, 3.5f);
  EXPECT_EQ(points[1].y, 4.25f);
  EXPECT_EQ(points[1].scale, 1.f);
  EXPECT_EQ(points[1].orientation, 0.f);

  const std::vector<Keypoint> affine = ReadFeatFile(Golden("affine.feat"));
  ASSERT_EQ(affine.size(), 2u);
  EXPECT_EQ(affine[0].x, 100.f);
  EXPECT_EQ(affine[0].y, 200.f);
  EXPECT_FLOAT_EQ(affine[0].scale, 2.f);  // sqrt(4 * 1)
  EXPECT_EQ(affine[0].orientation, 0.5f);
  EXPECT_FLOAT_EQ(affine[1].scale, 6.f);  // sqrt(9 * 4)
  EXPECT_EQ(affine[1].orientation, -0.25f);
}

TEST(OpenMvgFeat, RoundTripIsExactForAnyFloat) {
  const std::vector<Keypoint> keypoints = {
      {1.f / 3.f, 2.f / 7.f, 1e-7f, 3.14159265f},
      {123456.789f, -0.f, 100000.f, 6.2831853f},
      {std::numeric_limits<float>::min(), std::numeric_limits<float>::max(), 0.1f, -1e30f},
      {1382.43f, 12.8117f, 1.64867f, 5.52236f},
  };
  const fs::path path = testing::ScratchDir("feat_roundtrip") / "a.feat";
  WriteFeatFile(path, keypoints);
  const std::vector<Keypoint> back = ReadFeatFile(path);
  ASSERT_EQ(back.size(), keypoints.size());
  for (size_t i = 0; i < keypoints.size(); ++i) {
    EXPECT_EQ(back[i].x, keypoints[i].x) << i;
    EXPECT_EQ(back[i].y, keypoints[i].y) << i;
    EXPECT_EQ(back[i].scale, keypoints[i].scale) << i;
    EXPECT_EQ(back[i].orientation, keypoints[i].orientation) << i;
  }
  // Values OpenMVG printed with 6 digits keep their 6 digits.
  EXPECT_NE(ReadFileToString(path).find("\n1382.43 12.8117 1.64867 5.52236\n"), std::string::npos);
}

TEST(OpenMvgFeat, RejectsGarbageMixedAndMissingFiles) {
  EXPECT_NE(ErrorMessage([] { ReadFeatFile(Golden("garbage.feat")); }).find("garbage.feat: line 2: 'x'"),
            std::string::npos);
  const fs::path dir = testing::ScratchDir("feat_bad");
  WriteText(dir / "mixed.feat", "1 2 3 4\n1 2\n");
  EXPECT_NE(ErrorMessage([&] { ReadFeatFile(dir / "mixed.feat"); }).find("line 2"), std::string::npos);
  WriteText(dir / "three.feat", "1 2 3\n");
  EXPECT_THROW(ReadFeatFile(dir / "three.feat"), Error);
  WriteText(dir / "nan.feat", "1 nan 3 4\n");
  EXPECT_THROW(ReadFeatFile(dir / "nan.feat"), Error);
  EXPECT_NE(ErrorMessage([&] { ReadFeatFile(dir / "missing.feat"); }).find("missing.feat"),
            std::string::npos);
}

TEST(OpenMvgDesc, ReadsAndRewritesGoldenFile) {
  const std::vector<Descriptor> descriptors = ReadDescFile(Golden("sift.desc"));
  ASSERT_EQ(descriptors.size(), 2u);
  for (int k = 0; k < kDescriptorSize; ++k) {
    EXPECT_EQ(descriptors[0][k], k);
    EXPECT_EQ(descriptors[1][k], 255 - k);
  }
  const fs::path out = testing::ScratchDir("desc_golden") / "sift.desc";
  WriteDescFile(out, descriptors);
  EXPECT_EQ(ReadFileToString(out), ReadFileToString(Golden("sift.desc")));
}

TEST(OpenMvgDesc, RejectsTruncatedAndMissingFiles) {
  EXPECT_NE(ErrorMessage([] { ReadDescFile(Golden("sift_truncated.desc")); }).find("sift_truncated.desc"),
            std::string::npos);
  const fs::path dir = testing::ScratchDir("desc_bad");
  WriteText(dir / "short.desc", "abc");  // not even the count
  EXPECT_THROW(ReadDescFile(dir / "short.desc"), Error);
  EXPECT_THROW(ReadDescFile(dir / "missing.desc"), Error);
}

TEST(OpenMvgImageDescriber, WritesWhatCerealWritesAndReadsTheNames) {
  const fs::path out = testing::ScratchDir("describer") / "image_describer.json";
  WriteSiftImageDescriber(out);
  EXPECT_EQ(ReadFileToString(out), ReadFileToString(Golden("image_describer_sift.json")));
  const ImageDescriberInfo info = ReadImageDescriber(out);
  EXPECT_EQ(info.describer_name, "SIFT_Image_describer");
  EXPECT_EQ(info.regions_type, "SIFT_Regions");
  EXPECT_NO_THROW(RequireSiftRegions(info, out));
}

TEST(OpenMvgImageDescriber, RejectsRegionsWeCannotUse) {
  const ImageDescriberInfo akaze = ReadImageDescriber(Golden("image_describer_akaze.json"));
  EXPECT_EQ(akaze.regions_type, "AKAZE_Float_Regions");
  const std::string message =
      ErrorMessage([&] { RequireSiftRegions(akaze, Golden("image_describer_akaze.json")); });
  EXPECT_NE(message.find("AKAZE_Float_Regions"), std::string::npos);
  EXPECT_EQ(message.find('\n'), std::string::npos);
  EXPECT_THROW(ReadImageDescriber(Golden("sift.feat")), Error);  // not JSON
}

SfmData TwoViews() {
  SfmData data;
  data.views[3].id_view = 3;
  data.views[3].filename = "left.jpg";
  data.views[7].id_view = 7;
  data.views[7].filename = "right.image.png";
  return data;
}

FeaturesPerView TwoViewFeatures() {
  FeaturesPerView features;
  features[3].keypoints = {{1.25f, 2.5f, 3.f, 0.5f}, {10.f, 20.f, 1.f, 6.f}};
  features[3].descriptors.resize(2);
  features[3].descriptors[0].fill(7);
  features[3].descriptors[1].fill(200);
  features[7].keypoints = {{5.f, 6.f, 2.f, 1.f}};
  features[7].descriptors.resize(1);
  features[7].descriptors[0].fill(42);
  return features;
}

TEST(OpenMvgProjectFeatures, WriteThenReadGivesTheSameFeatures) {
  const fs::path dir = testing::ScratchDir("project_features");
  std::vector<size_t> progress;
  WriteOpenMvgFeatures(TwoViews(), TwoViewFeatures(), dir);
  EXPECT_TRUE(fs::exists(dir / "left.feat"));
  EXPECT_TRUE(fs::exists(dir / "right.image.desc"));
  EXPECT_TRUE(fs::exists(dir / "image_describer.json"));
  const FeaturesPerView back =
      ReadOpenMvgFeatures(TwoViews(), dir, true, [&](const std::string&, size_t done, size_t total) {
        EXPECT_EQ(total, 2u);
        progress.push_back(done);
      });
  EXPECT_EQ(progress, (std::vector<size_t>{0, 1, 2}));
  const FeaturesPerView expected = TwoViewFeatures();
  ASSERT_EQ(back.size(), 2u);
  for (const auto& [view_id, set] : expected) {
    ASSERT_EQ(back.at(view_id).size(), set.size());
    EXPECT_EQ(back.at(view_id).descriptors, set.descriptors);
    for (size_t i = 0; i < set.size(); ++i) {
      EXPECT_EQ(back.at(view_id).keypoints[i].x, set.keypoints[i].x);
      EXPECT_EQ(back.at(view_id).keypoints[i].orientation, set.keypoints[i].orientation);
    }
  }
  EXPECT_TRUE(ReadOpenMvgFeatures(TwoViews(), dir, false).at(3).descriptors.empty());
}

TEST(OpenMvgProjectFeatures, ReportsMissingFilesAndInconsistentCounts) {
  const fs::path dir = testing::ScratchDir("project_features_bad");
  WriteOpenMvgFeatures(TwoViews(), TwoViewFeatures(), dir);
  fs::remove(dir / "right.image.feat");
  EXPECT_NE(ErrorMessage([&] { ReadOpenMvgFeatures(TwoViews(), dir, false); }).find("right.image.feat"),
            std::string::npos);

  WriteOpenMvgFeatures(TwoViews(), TwoViewFeatures(), dir);
  WriteDescFile(dir / "left.desc", std::vector<Descriptor>(3));
  EXPECT_NE(ErrorMessage([&] { ReadOpenMvgFeatures(TwoViews(), dir, true); }).find("left.desc"),
            std::string::npos);

  fs::copy_file(Golden("image_describer_akaze.json"), dir / "image_describer.json",
                fs::copy_options::overwrite_existing);
  EXPECT_NE(ErrorMessage([&] { ReadOpenMvgFeatures(TwoViews(), dir, true); }).find("AKAZE_Float_Regions"),
            std::string::npos);
  // Positions alone do not depend on the regions type.
  EXPECT_EQ(ReadOpenMvgFeatures(TwoViews(), dir, false).at(3).size(), 2u);
}

TEST(OpenMvgProjectFeatures, RefusesToWriteAmbiguousOrInconsistentFeatures) {
  const fs::path dir = testing::ScratchDir("project_features_refused");
  SfmData same_basename = TwoViews();
  same_basename.views[7].filename = "left.png";
  EXPECT_THROW(WriteOpenMvgFeatures(same_basename, TwoViewFeatures(), dir), Error);
  FeaturesPerView unknown_view = TwoViewFeatures();
  unknown_view[99].keypoints.resize(1);
  EXPECT_THROW(WriteOpenMvgFeatures(TwoViews(), unknown_view, dir), Error);
  FeaturesPerView bad_count = TwoViewFeatures();
  bad_count[7].descriptors.resize(5);
  EXPECT_THROW(WriteOpenMvgFeatures(TwoViews(), bad_count, dir), Error);
  EXPECT_TRUE(fs::is_empty(dir));  // validation happens before any file is written
}

TEST(OpenMvgProjectFeatures, ReadsTheRealSceauxCastleProjectAndRewritesItExactly) {
  PRUNESFM_REQUIRE_SHARED("formats/openmvg/sceaux_castle/matches", matches_dir);
  const SfmData scene =
      ReadSfmData(matches_dir / "sfm_data.json", SfmDataParts::kViews | SfmDataParts::kIntrinsics);
  ASSERT_EQ(scene.views.size(), 11u);
  EXPECT_EQ(ReadImageDescriber(matches_dir / "image_describer.json").regions_type, "SIFT_Regions");
  const FeaturesPerView features = ReadOpenMvgFeatures(scene, matches_dir, true);
  ASSERT_EQ(features.size(), 11u);
  const fs::path out = testing::ScratchDir("sceaux_features");
  WriteOpenMvgFeatures(scene, features, out);
  for (const auto& [view_id, view] : scene.views) {
    const FeatureSet& set = features.at(view_id);
    EXPECT_GT(set.size(), 1000u) << view.filename;
    EXPECT_EQ(set.descriptors.size(), set.size()) << view.filename;
    for (const Keypoint& k : set.keypoints) {
      ASSERT_TRUE(k.x >= 0.f && k.x < static_cast<float>(view.width)) << view.filename << " x " << k.x;
      ASSERT_TRUE(k.y >= 0.f && k.y < static_cast<float>(view.height)) << view.filename << " y " << k.y;
      ASSERT_GT(k.scale, 0.f);
      ASSERT_TRUE(k.orientation >= 0.f && k.orientation <= 2.f * static_cast<float>(M_PI) + 1e-5f);
    }
    for (const char* extension : {".feat", ".desc"}) {
      EXPECT_EQ(ReadFileToString(FeatureFilePath(view, out, extension)),
                ReadFileToString(FeatureFilePath(view, matches_dir, extension)))
          << view.filename << extension;
    }
  }
  EXPECT_EQ(ReadFileToString(out / "image_describer.json"),
            ReadFileToString(matches_dir / "image_describer.json"));
}

}  // namespace
}  // namespace sfm_pruning::openmvg_features_test
