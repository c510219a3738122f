// prunesfm convert: every format pair the command supports, and every kind of bad input the
// foundation issue lists (one line on stderr naming the file, exit 1, no output left behind).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "run_prunesfm.hpp"
#include "sfm_pruning/io/model_io.hpp"
#include "sfm_pruning/io/openmvg_sfm_data.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning::testing {
namespace {
namespace fs = std::filesystem;

// Writes `text` to `path` (test input, not product output).
void WriteText(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

std::string ReadText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

void ExpectOneLineErrorNaming(const CommandResult& result, const std::string& name) {
  EXPECT_EQ(result.exit_code, 1) << result.err;
  EXPECT_EQ(CountLines(result.err), 1) << result.err;
  EXPECT_NE(result.err.find(name), std::string::npos) << result.err;
}

// The real OpenMVG 2.1 reconstruction goes sfm_data.json -> COLMAP (bin and txt) -> sfm_data.bin
// -> sfm_data.json; poses and points survive every hop.
TEST(CliConvert, RealOpenMvgReconstructionThroughEveryFormat) {
  PRUNESFM_REQUIRE_SHARED("formats/openmvg/sceaux_castle/reconstruction_global/sfm_data.json", input);
  const fs::path dir = ScratchDir("cli_convert_chain");
  const std::vector<std::pair<fs::path, std::vector<std::string>>> hops = {
      {dir / "colmap_bin", {}},
      {dir / "colmap_txt", {"--output_type", "TXT"}},
      {dir / "model.bin", {}},
      {dir / "model.json", {}},
      {dir / "model.ply", {}},
  };
  fs::path previous = input;
  for (const auto& [output, extra] : hops) {
    std::vector<std::string> args = {"convert", "--input", previous.string(), "--output", output.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const CommandResult result = RunPrunesfm(args);
    ASSERT_EQ(result.exit_code, 0) << result.err;
    if (output.extension() != ".ply") previous = output;
  }
  const SfmData original = ReadSfmData(input);
  const SfmData back = ReadSfmData(dir / "model.json");
  ASSERT_EQ(back.poses.size(), original.poses.size());
  ASSERT_EQ(back.structure.size(), original.structure.size());
  // COLMAP stores rotations as quaternions and text with 17 digits: equal to ~1e-12.
  for (const auto& [id, view] : original.views) {
    const auto match = std::find_if(back.views.begin(), back.views.end(),
                                    [&](const auto& entry) { return entry.second.filename == view.filename; });
    ASSERT_NE(match, back.views.end()) << view.filename;
    const Pose& a = original.PoseOf(view);
    const Pose& b = back.PoseOf(match->second);
    EXPECT_LT((a.rotation - b.rotation).norm(), 1e-12);
    EXPECT_LT((a.center - b.center).norm(), 1e-9);
  }
  const SfmData points = ReadModel(dir / "model.ply");
  EXPECT_EQ(points.structure.size(), original.structure.size() + original.poses.size());
}

TEST(CliConvert, HandMadeGoldenFileSurvivesJsonBinJson) {
  const fs::path golden = TestDataDir() / "openmvg_json" / "legacy_v02_value0.json";
  const fs::path dir = ScratchDir("cli_convert_golden");
  ASSERT_EQ(RunPrunesfm({"convert", "-i", golden.string(), "-o", (dir / "a.bin").string()}).exit_code, 0);
  ASSERT_EQ(RunPrunesfm({"convert", "-i", (dir / "a.bin").string(), "-o", (dir / "b.json").string()}).exit_code, 0);
  EXPECT_EQ(ReadSfmData(golden), ReadSfmData(dir / "b.json"));
}

// fx != fy (COLMAP's PINHOLE) has no place in OpenMVG's binary archive: refused, not rounded.
TEST(CliConvert, AnisotropicFocalCannotGoToSfmDataBin) {
  const fs::path golden = TestDataDir() / "openmvg_json" / "all_types.json";
  const fs::path dir = ScratchDir("cli_convert_fxfy");
  const CommandResult result = RunPrunesfm({"convert", "-i", golden.string(), "-o", (dir / "a.bin").string()});
  ExpectOneLineErrorNaming(result, "a.bin");
  EXPECT_NE(result.err.find("fx != fy"), std::string::npos) << result.err;
  EXPECT_FALSE(fs::exists(dir / "a.bin"));
}

TEST(CliConvert, MissingInput) {
  const fs::path dir = ScratchDir("cli_convert_missing");
  const CommandResult result =
      RunPrunesfm({"convert", "-i", (dir / "absent.json").string(), "-o", (dir / "out.json").string()});
  ExpectOneLineErrorNaming(result, "absent.json");
  EXPECT_FALSE(fs::exists(dir / "out.json"));
}

// Each damaged input: the file name and the exact problem appear on one line, nothing is written.
TEST(CliConvert, DamagedSfmDataGivesOneLineAndNoOutput) {
  const fs::path golden = TestDataDir() / "openmvg_json" / "all_types.json";
  const std::string text = ReadText(golden);
  ASSERT_FALSE(text.empty());
  const fs::path dir = ScratchDir("cli_convert_damaged");
  struct Damage {
    const char* name;
    std::string content;
    const char* expected;
  };
  std::string unknown_model = text;
  unknown_model.replace(unknown_model.find("\"pinhole_radial_k3\""), 19, "\"pinhole_radial_k9\"");
  std::string wrong_type = text;
  wrong_type.replace(wrong_type.find("\"width\": "), 9, "\"width\": \"wide\", \"w\": ");
  std::string dangling = text;
  dangling.replace(dangling.find("\"id_feat\""), 0, "\"ignored\": 0, ");
  const std::vector<Damage> damages = {
      {"truncated.json", text.substr(0, text.size() / 2), "truncated.json"},
      {"unknown_model.json", unknown_model, "pinhole_radial_k9"},
      {"wrong_type.json", wrong_type, "width"},
      {"empty.json", "", "empty.json"},
      {"not_json.json", "\x89PNG\r\n\x1a\n binary garbage", "not_json.json"},
  };
  for (const Damage& damage : damages) {
    SCOPED_TRACE(damage.name);
    WriteText(dir / damage.name, damage.content);
    const fs::path output = dir / (std::string(damage.name) + ".out.json");
    const CommandResult result = RunPrunesfm({"convert", "-i", (dir / damage.name).string(), "-o", output.string()});
    ExpectOneLineErrorNaming(result, damage.expected);
    EXPECT_FALSE(fs::exists(output));
  }
}

TEST(CliConvert, ObservationOfMissingViewIsRejected) {
  const fs::path dir = ScratchDir("cli_convert_dangling");
  const std::string json = R"({
    "sfm_data_version": "0.3", "root_path": "", "views": [], "intrinsics": [], "extrinsics": [],
    "structure": [{"key": 0, "value": {"X": [1.0, 2.0, 3.0],
                   "observations": [{"key": 7, "value": {"id_feat": 0, "x": [1.0, 2.0]}}]}}],
    "control_points": []})";
  WriteText(dir / "dangling.json", json);
  const CommandResult result =
      RunPrunesfm({"convert", "-i", (dir / "dangling.json").string(), "-o", (dir / "out.json").string()});
  ExpectOneLineErrorNaming(result, "dangling.json");
  EXPECT_NE(result.err.find("view 7"), std::string::npos) << result.err;
  EXPECT_FALSE(fs::exists(dir / "out.json"));
}

TEST(CliConvert, ForeignFileAsColmapModelIsRejected) {
  const fs::path dir = ScratchDir("cli_convert_foreign");
  fs::create_directories(dir / "model");
  WriteText(dir / "model" / "cameras.bin", "SQLite format 3\0 not a COLMAP model at all");
  const CommandResult result =
      RunPrunesfm({"convert", "-i", (dir / "model").string(), "-o", (dir / "out.json").string()});
  ExpectOneLineErrorNaming(result, "model");
  EXPECT_FALSE(fs::exists(dir / "out.json"));
}

TEST(CliConvert, UnknownExtensionAndBadOutputType) {
  const fs::path dir = ScratchDir("cli_convert_ext");
  WriteText(dir / "model.xyz", "1 2 3\n");
  ExpectOneLineErrorNaming(RunPrunesfm({"convert", "-i", (dir / "model.xyz").string(), "-o", (dir / "o.json").string()}),
                           "model.xyz");
  const CommandResult bad_type = RunPrunesfm(
      {"convert", "-i", (TestDataDir() / "openmvg_json" / "all_types.json").string(), "-o", (dir / "m").string(),
       "--output_type", "XML"});
  EXPECT_NE(bad_type.exit_code, 0);
  EXPECT_FALSE(fs::exists(dir / "m"));
}

}  // namespace
}  // namespace sfm_pruning::testing
