// prunesfm export: every format from a small rendered scene with distortion, and bad input.
#include <gtest/gtest.h>

#include <filesystem>

#include "export/rendered_scene.hpp"
#include "run_prunesfm.hpp"
#include "sfm_pruning/export/point_colors.hpp"
#include "sfm_pruning/io/colmap_model.hpp"
#include "sfm_pruning/io/openmvg_sfm_data.hpp"
#include "sfm_pruning/io/openmvs_scene.hpp"
#include "sfm_pruning/io/ply.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning::testing {
namespace {
namespace fs = std::filesystem;

// A model with its images: sfm_data.json whose root_path is the image folder.
fs::path MakeModel(const fs::path& dir, SfmData* data) {
  const CameraIntrinsics camera(CameraModel::kPinholeRadialK1, 160, 120, {140.0, 80.5, 59.0, -0.2});
  *data = MakeRenderedScene(camera, dir / "images");
  WriteSfmData(*data, dir / "sfm_data.json");
  return dir / "sfm_data.json";
}

CommandResult Export(const fs::path& model, const std::string& format, const fs::path& output,
                     std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"export",   "--model",       model.string(),  "--format", format,
                                   "--output", output.string(), "--num_threads", "2"};
  args.insert(args.end(), extra.begin(), extra.end());
  return RunPrunesfm(args);
}

TEST(CliExport, WritesEveryFormat) {
  const fs::path dir = ScratchDir("cli_export");
  SfmData data;
  const fs::path model = MakeModel(dir, &data);
  SfmData colored = data;
  ColorLandmarksFromImages(&colored, dir / "images");

  CommandResult result = Export(model, "openmvs", dir / "mvs");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const OpenMvsScene scene = ReadOpenMvsScene(dir / "mvs" / "scene.mvs");
  ASSERT_EQ(scene.images.size(), 3u);
  for (const OpenMvsScene::Image& image : scene.images)
    EXPECT_TRUE(fs::is_regular_file(dir / "mvs" / image.name));
  EXPECT_EQ(scene.vertex_colors[7][0], colored.structure[7].color[2]);

  result = Export(model, "colmap-undistorted", dir / "dense", {"--keep_all_pixels"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const SfmData undistorted = ReadColmapModel(dir / "dense" / "sparse");
  EXPECT_FALSE(undistorted.intrinsics.begin()->second.HasDistortion());
  EXPECT_TRUE(fs::is_regular_file(dir / "dense" / "stereo" / "patch-match.cfg"));
  EXPECT_TRUE(fs::is_regular_file(dir / "dense" / "images" / "view2.png"));

  result = Export(model, "colmap", dir / "sparse", {"--output_type", "TXT"});
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const SfmData sparse = ReadColmapModel(dir / "sparse");
  EXPECT_TRUE(fs::is_regular_file(dir / "sparse" / "cameras.txt"));
  EXPECT_EQ(sparse.intrinsics.begin()->second, data.intrinsics.at(0));  // distortion kept
  EXPECT_EQ(sparse.structure.at(7).color, colored.structure[7].color);

  result = Export(model, "ply", dir / "points.ply");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const SfmData points = ReadPlyPoints(dir / "points.ply");
  ASSERT_EQ(points.structure.size(), 40u);  // points only, no camera centres
  size_t k = 0;
  for (const auto& [id, landmark] : points.structure)
    EXPECT_EQ(landmark.color, colored.structure.at(k++).color);

  result = Export(model, "json", dir / "coloured.json");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_EQ(ReadSfmData(dir / "coloured.json").root_path, (dir / "images").string());
}

TEST(CliExport, BadInputGivesOneLineErrors) {
  const fs::path dir = ScratchDir("cli_export_errors");
  SfmData data;
  const fs::path model = MakeModel(dir, &data);
  const auto expect_error = [](const CommandResult& result, const std::string& text) {
    EXPECT_EQ(result.exit_code, 1) << result.err;
    EXPECT_EQ(CountLines(result.err), 1) << result.err;
    EXPECT_NE(result.err.find(text), std::string::npos) << result.err;
  };
  expect_error(Export(model, "openmvs", dir / "mvs", {"--images", (dir / "nowhere").string()}),
               (dir / "nowhere").string() + ": image folder does not exist");
  expect_error(Export(model, "ply", dir / "points.txt"), "--format ply writes a file ending in .ply");
  fs::remove(dir / "images" / "view1.png");
  expect_error(Export(model, "colmap-undistorted", dir / "dense"), (dir / "images" / "view1.png").string());
  EXPECT_FALSE(fs::exists(dir / "dense"));
  data.root_path.clear();
  WriteSfmData(data, dir / "no_root.json");
  expect_error(Export(dir / "no_root.json", "openmvs", dir / "mvs"), "needs the images; give --images");
  // A PLY of a model without images (a synthetic one) keeps the model's colours.
  const CommandResult ply = Export(dir / "no_root.json", "ply", dir / "no_images.ply");
  EXPECT_EQ(ply.exit_code, 0) << ply.err;
  EXPECT_EQ(ReadPlyPoints(dir / "no_images.ply").structure.size(), data.structure.size());
  expect_error(Export(dir / "missing.json", "ply", dir / "p.ply"), (dir / "missing.json").string());
}

}  // namespace
}  // namespace sfm_pruning::testing
