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

// A pid that no process has: larger than any Linux pid_max (4194304).
constexpr const char* kDeadPid = "99999999";

TEST(OutputFolder, NewEmptyAndMarkedFoldersAreAcceptedOthersRefused) {
  const fs::path scratch = testing::ScratchDir("output_folder_check");
  EXPECT_NO_THROW(CheckOutputFolder(scratch / "new", false));
  EXPECT_NO_THROW(CheckOutputFolder(scratch, false));  // exists, empty

  WriteText(scratch / "user" / "precious.txt", "x");
  EXPECT_THROW(CheckOutputFolder(scratch / "user", false), Error);
  EXPECT_NO_THROW(CheckOutputFolder(scratch / "user", true));
  EXPECT_EQ(ReadText(scratch / "user" / "precious.txt"), "x");  // checking never writes

  ClaimOutputFolder(scratch / "ours");
  WriteText(scratch / "ours" / "sfm_data.json", "{}");
  EXPECT_TRUE(fs::exists(scratch / "ours" / kOutputFolderMarker));
  EXPECT_NO_THROW(CheckOutputFolder(scratch / "ours", false));
}

TEST(OutputFolder, FilesAndEmptyPathsAreNeverOutputFolders) {
  const fs::path scratch = testing::ScratchDir("output_folder_file");
  WriteText(scratch / "notes.txt", "keep me");
  EXPECT_THROW(CheckOutputFolder(scratch / "notes.txt", false), Error);
  EXPECT_THROW(CheckOutputFolder(scratch / "notes.txt", true), Error);
  EXPECT_THROW(CheckOutputFolder("", true), Error);
  EXPECT_THROW(WriteFileAtomically("", false, [](std::ostream& out) { out << "x"; }), Error);
  EXPECT_THROW(WriteDirectoryAtomically("", [](const fs::path&) {}), Error);
  EXPECT_THROW(WriteDirectoryAtomically(scratch / "notes.txt", [](const fs::path&) {}), Error);
  EXPECT_EQ(ReadText(scratch / "notes.txt"), "keep me");
}

TEST(OutputFolder, WholeFolderWritesCarryTheMarker) {
  const fs::path dir = testing::ScratchDir("output_folder_whole") / "scene";
  WriteDirectoryAtomically(dir, [](const fs::path& tmp) { WriteText(tmp / "a.txt", "1"); });
  EXPECT_TRUE(fs::exists(dir / kOutputFolderMarker));
  EXPECT_NO_THROW(CheckOutputFolder(dir, false));  // a later run may replace it
}

TEST(StaleTemporaries, LeftoversOfDeadProcessesAreCleanedOthersKept) {
  const fs::path scratch = testing::ScratchDir("output_folder_stale");
  const fs::path target = scratch / "sparse0";
  const std::string own_pid = std::to_string(::getpid());
  WriteText(scratch / ("sparse0.tmp." + std::string(kDeadPid)) / "cameras.bin", "half");
  WriteText(scratch / ("sparse0.tmp." + own_pid) / "cameras.bin", "in progress");
  WriteText(scratch / ("other.tmp." + std::string(kDeadPid)), "not ours to judge");
  WriteText(scratch / "sparse0.tmp.notapid", "user file");
  RemoveStaleTemporaries(target);
  EXPECT_FALSE(fs::exists(scratch / ("sparse0.tmp." + std::string(kDeadPid))));
  EXPECT_TRUE(fs::exists(scratch / ("sparse0.tmp." + own_pid)));
  EXPECT_TRUE(fs::exists(scratch / ("other.tmp." + std::string(kDeadPid))));
  EXPECT_TRUE(fs::exists(scratch / "sparse0.tmp.notapid"));
}

TEST(StaleTemporaries, TheOldVersionComesBackWhenTheNewNeverMovedIn) {
  const fs::path scratch = testing::ScratchDir("output_folder_old");
  // Interrupted between "move the old aside" and "move the new in": only the old one is left.
  WriteText(scratch / ("scene.old." + std::string(kDeadPid)) / "a.txt", "old");
  RemoveStaleTemporaries(scratch / "scene");
  EXPECT_EQ(ReadText(scratch / "scene" / "a.txt"), "old");
  EXPECT_FALSE(fs::exists(scratch / ("scene.old." + std::string(kDeadPid))));

  // Interrupted after the new one moved in: the old one is removed.
  WriteText(scratch / ("scene.old." + std::string(kDeadPid)) / "a.txt", "older");
  RemoveStaleTemporaries(scratch / "scene");
  EXPECT_EQ(ReadText(scratch / "scene" / "a.txt"), "old");
  EXPECT_FALSE(fs::exists(scratch / ("scene.old." + std::string(kDeadPid))));
}

TEST(StaleTemporaries, AWholeFolderWriteCleansAfterAnInterruptedOne) {
  const fs::path scratch = testing::ScratchDir("output_folder_rewrite");
  WriteText(scratch / ("scene.tmp." + std::string(kDeadPid)) / "a.txt", "half");
  WriteText(scratch / ("scene.old." + std::string(kDeadPid)) / "a.txt", "old");
  WriteDirectoryAtomically(scratch / "scene", [](const fs::path& tmp) { WriteText(tmp / "a.txt", "new"); });
  EXPECT_EQ(ReadText(scratch / "scene" / "a.txt"), "new");
  size_t entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(scratch)) ++entries;
  EXPECT_EQ(entries, 1u);
}

}  // namespace
}  // namespace sfm_pruning
