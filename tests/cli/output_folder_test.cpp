// What the commands do with the folder they are told to write: a folder of the user's is never
// replaced or mixed into without --overwrite, a file is never turned into a folder, and a run
// folder holds the outputs of one run.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "run_prunesfm.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning::testing {
namespace {
namespace fs = std::filesystem;

std::string ReadText(const fs::path& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

CommandResult Synth(const fs::path& out, const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args = {"synth", "--scene", "clean", "--num_views", "6", "-o", out.string()};
  args.insert(args.end(), extra.begin(), extra.end());
  return RunPrunesfm(args);
}

TEST(CliOutputFolder, AFolderOfTheUsersIsNotReplaced) {
  const fs::path scratch = ScratchDir("cli_output_user_folder");
  std::ofstream(scratch / "precious.txt") << "x";
  const CommandResult synth = Synth(scratch);
  EXPECT_EQ(synth.exit_code, 1);
  EXPECT_EQ(CountLines(synth.err), 1) << synth.err;
  EXPECT_NE(synth.err.find(scratch.string()), std::string::npos) << synth.err;
  EXPECT_NE(synth.err.find("--overwrite"), std::string::npos) << synth.err;
  EXPECT_EQ(ReadText(scratch / "precious.txt"), "x");

  ASSERT_EQ(Synth(scratch / "scene").exit_code, 0);
  for (const std::vector<std::string>& command :
       {std::vector<std::string>{"convert", "-i", (scratch / "scene" / "sfm_data.json").string(), "-o", scratch.string()},
        std::vector<std::string>{"export", "-i", (scratch / "scene" / "sfm_data.json").string(), "--format", "colmap",
                                 "-o", scratch.string()},
        std::vector<std::string>{"reconstruct", "--sfm_data", (scratch / "scene" / "sfm_data.json").string(),
                                 "--matches_dir", (scratch / "scene" / "matches").string(), "-o", scratch.string()}}) {
    const CommandResult result = RunPrunesfm(command);
    EXPECT_EQ(result.exit_code, 1) << command[0] << ": " << result.err;
    EXPECT_EQ(ReadText(scratch / "precious.txt"), "x") << command[0];
  }
}

// --overwrite replaces a folder written whole (its help says so) and writes into a run folder,
// which stays unmarked: no command that replaces whole folders takes it for an output of its own.
TEST(CliOutputFolder, OverwriteIsTheUsersExplicitYes) {
  const fs::path scratch = ScratchDir("cli_output_overwrite");
  std::ofstream(scratch / "notes.txt") << "x";
  const CommandResult result = Synth(scratch, {"--overwrite"});
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(fs::exists(scratch / "sfm_data.json"));
  EXPECT_FALSE(fs::exists(scratch / "notes.txt"));

  const fs::path user = scratch / "user";
  fs::create_directories(user);
  std::ofstream(user / "notes.txt") << "x";
  const auto reconstruct = [&](const std::vector<std::string>& extra) {
    std::vector<std::string> args = {"reconstruct", "--engine", "GLOBAL", "--sfm_data",
                                     (scratch / "sfm_data.json").string(), "--matches_dir",
                                     (scratch / "matches").string(), "-o", user.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    return RunPrunesfm(args);
  };
  EXPECT_EQ(reconstruct({}).exit_code, 1);
  const CommandResult into = reconstruct({"--overwrite"});
  EXPECT_EQ(into.exit_code, 0) << into.err;
  EXPECT_EQ(ReadText(user / "notes.txt"), "x");
  EXPECT_TRUE(fs::exists(user / "sfm_data.json"));
  // It now holds a run, which a later run may write into again; a command that replaces whole
  // folders still may not take it.
  const CommandResult exported = RunPrunesfm({"export", "-i", (user / "sfm_data.json").string(), "--format",
                                              "colmap", "-o", user.string()});
  EXPECT_EQ(exported.exit_code, 1) << exported.err;
  EXPECT_EQ(ReadText(user / "notes.txt"), "x");
}

TEST(CliOutputFolder, AnOutputOfAnotherKindIsNotReplaced) {
  const fs::path scratch = ScratchDir("cli_output_kind");
  ASSERT_EQ(Synth(scratch / "scene").exit_code, 0);
  const CommandResult run = RunPrunesfm({"reconstruct", "--engine", "GLOBAL", "--sfm_data",
                                         (scratch / "scene" / "sfm_data.json").string(), "--matches_dir",
                                         (scratch / "scene" / "matches").string(), "-o", (scratch / "run").string()});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const CommandResult exported = RunPrunesfm({"export", "-i", (scratch / "scene" / "sfm_data.json").string(),
                                              "--format", "colmap", "-o", (scratch / "run").string()});
  EXPECT_EQ(exported.exit_code, 1);
  EXPECT_NE(exported.err.find("holds a prunesfm run, not a COLMAP model"), std::string::npos) << exported.err;
  EXPECT_TRUE(fs::exists(scratch / "run" / "timings.json"));
  const CommandResult into_scene = RunPrunesfm({"convert", "-i", (scratch / "run" / "sfm_data.json").string(), "-o",
                                                (scratch / "scene").string()});
  EXPECT_EQ(into_scene.exit_code, 1);
  EXPECT_TRUE(fs::exists(scratch / "scene" / "database.db"));
}

// Writing the output would replace what is read: refused before any work, --overwrite or not.
TEST(CliOutputFolder, AnOutputOverItsInputIsRefused) {
  const fs::path scratch = ScratchDir("cli_output_over_input");
  ASSERT_EQ(Synth(scratch / "scene").exit_code, 0);
  const fs::path model = scratch / "scene" / "ground_truth" / "sfm_data.json";
  ASSERT_EQ(RunPrunesfm({"convert", "-i", model.string(), "-o", (scratch / "model.bin").string()}).exit_code, 0);
  const std::string before = ReadText(scratch / "model.bin");
  const CommandResult same_file =
      RunPrunesfm({"convert", "-i", (scratch / "model.bin").string(), "-o", (scratch / "model.bin").string()});
  EXPECT_EQ(same_file.exit_code, 1);
  EXPECT_EQ(CountLines(same_file.err), 1) << same_file.err;
  EXPECT_NE(same_file.err.find("model.bin: the output is the input"), std::string::npos) << same_file.err;
  EXPECT_EQ(ReadText(scratch / "model.bin"), before);
  // A folder holding the input, even one --overwrite may replace.
  const CommandResult holder = RunPrunesfm({"export", "-i", model.string(), "--format", "colmap", "-o",
                                            (scratch / "scene").string(), "--overwrite"});
  EXPECT_EQ(holder.exit_code, 1);
  EXPECT_NE(holder.err.find("holds the input"), std::string::npos) << holder.err;
  EXPECT_TRUE(fs::exists(model));
  EXPECT_TRUE(fs::exists(scratch / "scene" / "database.db"));
}

TEST(CliOutputFolder, AFileIsNeverReplacedByAFolderAndAnEmptyPathIsRefused) {
  const fs::path scratch = ScratchDir("cli_output_file");
  const fs::path file = scratch / "existing_file.txt";
  std::ofstream(file) << "keep";
  for (const bool overwrite : {false, true}) {
    const CommandResult result = Synth(file, overwrite ? std::vector<std::string>{"--overwrite"}
                                                       : std::vector<std::string>{});
    EXPECT_EQ(result.exit_code, 1) << result.err;
    EXPECT_EQ(CountLines(result.err), 1) << result.err;
    EXPECT_TRUE(fs::is_regular_file(file));
    EXPECT_EQ(ReadText(file), "keep");
  }
  const CommandResult empty = Synth("");
  EXPECT_EQ(empty.exit_code, 1) << empty.err;
  EXPECT_EQ(CountLines(empty.err), 1) << empty.err;
}

TEST(CliOutputFolder, ARunFolderHoldsTheOutputsOfTheLastRunOnly) {
  const fs::path scratch = ScratchDir("cli_output_rerun");
  ASSERT_EQ(Synth(scratch / "scene").exit_code, 0);
  const auto reconstruct = [&](const std::string& engine) {
    return RunPrunesfm({"reconstruct", "--engine", engine, "--sfm_data", (scratch / "scene" / "sfm_data.json").string(),
                        "--matches_dir", (scratch / "scene" / "matches").string(), "-o", (scratch / "out").string()});
  };
  ASSERT_EQ(reconstruct("GLOBAL_PRUNED").exit_code, 0);
  ASSERT_TRUE(fs::exists(scratch / "out" / "pruning_report.json"));
  const CommandResult global = reconstruct("GLOBAL");
  ASSERT_EQ(global.exit_code, 0) << global.err;
  EXPECT_FALSE(fs::exists(scratch / "out" / "pruning_report.json"));  // it described the earlier run
  EXPECT_TRUE(fs::exists(scratch / "out" / "timings.json"));

  // Without its completion record (timings.json, written last) the folder is an interrupted run.
  fs::remove(scratch / "out" / "timings.json");
  const CommandResult report =
      RunPrunesfm({"report", "--run", (scratch / "out").string(), "--output", (scratch / "report.html").string()});
  EXPECT_EQ(report.exit_code, 1) << report.err;
  EXPECT_NE(report.err.find("did not finish"), std::string::npos) << report.err;
}

}  // namespace
}  // namespace sfm_pruning::testing
