// prunesfm prune: the one-line errors (fast; the end-to-end runs are in prune_end_to_end_test.cpp).
#include <gtest/gtest.h>

#include <filesystem>

#include "run_prunesfm.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning::testing {
namespace {
namespace fs = std::filesystem;

// An 8-view clean scene: its database holds putative matches only, no two-view geometries.
const fs::path& SmallProject() {
  static const fs::path dir = []() {
    const std::string test_name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    const fs::path out = ScratchDir("cli_prune_scene_" + test_name) / "clean";
    const CommandResult result =
        RunPrunesfm({"synth", "--scene", "clean", "--seed", "2", "--num_views", "8", "--output", out.string()});
    EXPECT_EQ(result.exit_code, 0) << result.err;
    return out;
  }();
  return dir;
}

void ExpectOneLineError(const CommandResult& result, const std::string& expected) {
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(CountLines(result.err), 1) << result.err;
  EXPECT_NE(result.err.find(expected), std::string::npos) << result.err;
}

TEST(CliPrune, MissingDatabaseIsOneLine) {
  const fs::path scratch = ScratchDir("cli_prune_missing");
  ExpectOneLineError(RunPrunesfm({"prune", "--database", "/nonexistent/database.db", "--output",
                                  (scratch / "pruned.db").string()}),
                     "/nonexistent/database.db");
  EXPECT_FALSE(fs::exists(scratch / "pruned.db"));
}

TEST(CliPrune, DatabaseWithoutTwoViewGeometriesIsRefused) {
  const fs::path scratch = ScratchDir("cli_prune_unverified");
  const fs::path database = SmallProject() / "database.db";
  ExpectOneLineError(RunPrunesfm({"prune", "--database", database.string(), "--output",
                                  (scratch / "pruned.db").string()}),
                     database.string() + ": no two-view geometries");
  EXPECT_FALSE(fs::exists(scratch / "pruned.db"));
  EXPECT_FALSE(fs::exists(scratch / "pruned.pruning_report.json"));
}

TEST(CliPrune, InputMustBeExactlyOneOfDatabaseAndOpenMvg) {
  const fs::path scratch = ScratchDir("cli_prune_inputs");
  const std::string out = (scratch / "out.db").string();
  ExpectOneLineError(RunPrunesfm({"prune", "--output", out}), "give either --database");
  ExpectOneLineError(RunPrunesfm({"prune", "--database", (SmallProject() / "database.db").string(), "--sfm_data",
                                  (SmallProject() / "sfm_data.json").string(), "--output", out}),
                     "give either --database");
  ExpectOneLineError(RunPrunesfm({"prune", "--sfm_data", (SmallProject() / "sfm_data.json").string(), "--output",
                                  out}),
                     "--sfm_data needs --matches_dir");
}

TEST(CliPrune, ReportMustNotOverwriteTheOutput) {
  const fs::path scratch = ScratchDir("cli_prune_report_clash");
  const std::string out = (scratch / "pruned.txt").string();
  ExpectOneLineError(RunPrunesfm({"prune", "--sfm_data", (SmallProject() / "sfm_data.json").string(),
                                  "--matches_dir", (SmallProject() / "matches").string(), "--output", out,
                                  "--report", out}),
                     "--report must differ from --output");
}

}  // namespace
}  // namespace sfm_pruning::testing
