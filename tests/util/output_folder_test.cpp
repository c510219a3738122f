// Which folders the tools write into (util/output_folder.hpp) and what an interrupted write leaves
// (RemoveStaleTemporaries, WriteDirectoryAtomically in util/atomic_file.hpp).
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "sfm_pruning/util/atomic_file.hpp"
#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/output_folder.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning {
namespace {
namespace fs = std::filesystem;

void WriteText(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

std::string ReadText(const fs::path& path) { return ReadFileToString(path, false); }

// A pid that no process has: pids stay below pid_max, which is at most 4194304.
constexpr const char* kDeadPid = "4194304";

constexpr OutputFolderKind kRun = OutputFolderKind::kRun;
constexpr OutputFolderKind kModel = OutputFolderKind::kColmapModel;

TEST(OutputFolder, NewEmptyAndMarkedFoldersAreAcceptedOthersRefused) {
  const fs::path scratch = testing::ScratchDir("output_folder_check");
  EXPECT_TRUE(CheckOutputFolder(scratch / "new", kRun, false));
  EXPECT_TRUE(CheckOutputFolder(scratch, kRun, false));  // exists, empty

  WriteText(scratch / "user" / "precious.txt", "x");
  EXPECT_THROW(CheckOutputFolder(scratch / "user", kRun, false), Error);
  EXPECT_FALSE(CheckOutputFolder(scratch / "user", kRun, true));  // accepted, but not ours to mark
  EXPECT_EQ(ReadText(scratch / "user" / "precious.txt"), "x");    // checking never writes

  ClaimOutputFolder(scratch / "ours/", kRun);  // a trailing separator names the same folder
  WriteText(scratch / "ours" / "sfm_data.json", "{}");
  EXPECT_TRUE(fs::exists(scratch / "ours" / kOutputFolderMarker));
  EXPECT_TRUE(CheckOutputFolder(scratch / "ours", kRun, false));
  EXPECT_TRUE(CheckOutputFolder(scratch / "ours/", kRun, false));
}

TEST(OutputFolder, AnOutputOfAnotherKindIsNotReplaced) {
  const fs::path scratch = testing::ScratchDir("output_folder_kind");
  ClaimOutputFolder(scratch / "run", kRun);
  WriteText(scratch / "run" / "matches" / "sfm_data.json", "{}");
  try {
    CheckOutputFolder(scratch / "run", kModel, false);
    ADD_FAILURE() << "a COLMAP model export would replace a run folder";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("holds a prunesfm run, not a COLMAP model"), std::string::npos) << e.what();
  }
  // A run folder written before the markers is known by its run_manifest.json or view_graph.json.
  WriteText(scratch / "old_run" / "run_manifest.json", "{}");
  EXPECT_TRUE(CheckOutputFolder(scratch / "old_run", kRun, false));
  EXPECT_THROW(CheckOutputFolder(scratch / "old_run", kModel, false), Error);
}

TEST(OutputFolder, FilesAndEmptyPathsAreNeverOutputFolders) {
  const fs::path scratch = testing::ScratchDir("output_folder_file");
  WriteText(scratch / "notes.txt", "keep me");
  EXPECT_THROW(CheckOutputFolder(scratch / "notes.txt", kRun, false), Error);
  EXPECT_THROW(CheckOutputFolder(scratch / "notes.txt", kRun, true), Error);
  EXPECT_THROW(CheckOutputFolder("", kRun, true), Error);
  EXPECT_THROW(WriteFileAtomically("", false, [](std::ostream& out) { out << "x"; }), Error);
  EXPECT_THROW(WriteDirectoryAtomically("", kModel, [](const fs::path&) {}), Error);
  EXPECT_THROW(WriteDirectoryAtomically(scratch / "notes.txt", kModel, [](const fs::path&) {}), Error);
  EXPECT_EQ(ReadText(scratch / "notes.txt"), "keep me");
}

TEST(OutputFolder, WholeFolderWritesCarryTheMarker) {
  const fs::path dir = testing::ScratchDir("output_folder_whole") / "scene";
  WriteDirectoryAtomically(dir, kModel, [](const fs::path& tmp) { WriteText(tmp / "a.txt", "1"); });
  EXPECT_TRUE(fs::exists(dir / kOutputFolderMarker));
  EXPECT_TRUE(CheckOutputFolder(dir, kModel, false));  // a later model may replace it
  EXPECT_THROW(CheckOutputFolder(dir, kRun, false), Error);
  // With a trailing separator the folder is written in place, not inside itself.
  WriteDirectoryAtomically(dir.string() + "/", kModel, [](const fs::path& tmp) { WriteText(tmp / "b.txt", "2"); });
  EXPECT_TRUE(fs::exists(dir / "b.txt"));
  EXPECT_FALSE(fs::exists(dir / "a.txt"));
}

TEST(StaleTemporaries, LeftoversOfDeadProcessesAreCleanedOthersKept) {
  const fs::path scratch = testing::ScratchDir("output_folder_stale");
  const fs::path target = scratch / "sparse0";
  const std::string own_pid = std::to_string(::getpid());
  WriteText(scratch / ("sparse0.prunesfm-tmp." + std::string(kDeadPid)) / "cameras.bin", "half");
  WriteText(scratch / ("sparse0.prunesfm-tmp." + own_pid) / "cameras.bin", "in progress");
  WriteText(scratch / ("other.prunesfm-tmp." + std::string(kDeadPid)), "not ours to judge");
  WriteText(scratch / "sparse0.tmp.notapid", "user file");
  WriteText(scratch / "sparse0.old.20240115" / "a.txt", "the user's backup");
  WriteText(scratch / "sparse0.prunesfm-tmp.99999999999" / "a.txt", "not a pid Linux gives");
  RemoveStaleTemporaries(target);
  EXPECT_FALSE(fs::exists(scratch / ("sparse0.prunesfm-tmp." + std::string(kDeadPid))));
  EXPECT_TRUE(fs::exists(scratch / ("sparse0.prunesfm-tmp." + own_pid)));
  EXPECT_TRUE(fs::exists(scratch / ("other.prunesfm-tmp." + std::string(kDeadPid))));
  EXPECT_TRUE(fs::exists(scratch / "sparse0.tmp.notapid"));
  EXPECT_TRUE(fs::exists(scratch / "sparse0.old.20240115" / "a.txt"));
  EXPECT_TRUE(fs::exists(scratch / "sparse0.prunesfm-tmp.99999999999"));
}

TEST(StaleTemporaries, TheOldVersionComesBackWhenTheNewNeverMovedIn) {
  const fs::path scratch = testing::ScratchDir("output_folder_old");
  // Interrupted between "move the old aside" and "move the new in": only the old one is left.
  WriteText(scratch / ("scene.prunesfm-old." + std::string(kDeadPid)) / "a.txt", "old");
  RemoveStaleTemporaries(scratch / "scene");
  EXPECT_EQ(ReadText(scratch / "scene" / "a.txt"), "old");
  EXPECT_FALSE(fs::exists(scratch / ("scene.prunesfm-old." + std::string(kDeadPid))));

  // Interrupted after the new one moved in: the old one is removed.
  WriteText(scratch / ("scene.prunesfm-old." + std::string(kDeadPid)) / "a.txt", "older");
  RemoveStaleTemporaries(scratch / "scene");
  EXPECT_EQ(ReadText(scratch / "scene" / "a.txt"), "old");
  EXPECT_FALSE(fs::exists(scratch / ("scene.prunesfm-old." + std::string(kDeadPid))));
}

TEST(StaleTemporaries, AWholeFolderWriteCleansAfterAnInterruptedOne) {
  const fs::path scratch = testing::ScratchDir("output_folder_rewrite");
  WriteText(scratch / ("scene.prunesfm-tmp." + std::string(kDeadPid)) / "a.txt", "half");
  WriteText(scratch / ("scene.prunesfm-old." + std::string(kDeadPid)) / "a.txt", "old");
  WriteDirectoryAtomically(scratch / "scene", kModel, [](const fs::path& tmp) { WriteText(tmp / "a.txt", "new"); });
  EXPECT_EQ(ReadText(scratch / "scene" / "a.txt"), "new");
  size_t entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(scratch)) ++entries;
  EXPECT_EQ(entries, 1u);
}

}  // namespace
}  // namespace sfm_pruning
