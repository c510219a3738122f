#include <algorithm>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "run_prunesfm.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning::testing {
namespace {
namespace fs = std::filesystem;

TEST(Cli, HelpListsSubcommandsAndEngines) {
  const CommandResult result = RunPrunesfm({"--help"});
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_NE(result.out.find("convert"), std::string::npos) << result.out;
  EXPECT_NE(result.out.find("GLOBAL"), std::string::npos);
  EXPECT_NE(result.out.find("GLOBAL_PRUNED"), std::string::npos);
}

TEST(Cli, RunHelpFitsTwoScreensAndHelpAllListsEveryOption) {
  // --help keeps what most runs set, the presets included; the expert options collapse into one
  // line that --help_all expands.
  const CommandResult help = RunPrunesfm({"run", "--help"});
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_LE(std::count(help.out.begin(), help.out.end(), '\n'), 100) << help.out;
  for (const char* shown : {"--engine", "--prune_preset", "--refine_intrinsics", "--database", "--num_threads"}) {
    EXPECT_NE(help.out.find(shown), std::string::npos) << shown;
  }
  EXPECT_EQ(help.out.find("--prune_landmark_check_max_angle_deg"), std::string::npos);
  EXPECT_NE(help.out.find("expert options are not shown: --help_all lists them"), std::string::npos) << help.out;

  const CommandResult all = RunPrunesfm({"run", "--help_all"});
  EXPECT_EQ(all.exit_code, 0);
  for (const char* expert : {"--prune_landmark_check_max_angle_deg", "--flann_checks", "--refine_distortion",
                             "--solver_threads"}) {
    EXPECT_NE(all.out.find(expert), std::string::npos) << expert;
  }
  EXPECT_EQ(all.out.find("expert options are not shown"), std::string::npos);
}

TEST(Cli, NoSubcommandIsAnError) {
  const CommandResult result = RunPrunesfm({});
  EXPECT_NE(result.exit_code, 0);
}

TEST(Cli, UnknownOptionIsAnError) {
  const CommandResult result = RunPrunesfm({"convert", "--no_such_option", "1"});
  EXPECT_NE(result.exit_code, 0);
  EXPECT_FALSE(result.err.empty());
}

TEST(Cli, PositioningTracksWithTranslationAveragingIsRefused) {
  // Translation averaging has no positioning tracks; the option would be silently ignored.
  for (const char* command : {"reconstruct", "prune"}) {
    const CommandResult result = RunPrunesfm({command, "--database", "/nonexistent/database.db", "--output", "/tmp/x.db",
                                              "--positioning", "TRANSLATION_AVERAGING", "--positioning_tracks",
                                              "MATCH_STARS"});
    EXPECT_NE(result.exit_code, 0) << command;
    EXPECT_NE(result.err.find("needs --positioning GLOMAP"), std::string::npos) << result.err;
  }
}

TEST(Cli, PruneOffersTheModelAuditButNotHowTheFinalSolveStarts) {
  // `prune` runs GLOBAL_PRUNED's pruning, the audit included; it stops there, so how the final
  // solve starts from the audited model would be silently ignored.
  const CommandResult prune_help = RunPrunesfm({"prune", "--help_all"});
  EXPECT_EQ(prune_help.exit_code, 0);
  EXPECT_NE(prune_help.out.find("--prune_audit_enabled"), std::string::npos);
  EXPECT_NE(prune_help.out.find("--prune_landmark_check_max_angle_deg"), std::string::npos);
  const CommandResult prune = RunPrunesfm({"prune", "--database", "/nonexistent/database.db", "--output", "/tmp/x.db",
                                           "--prune_audit_refine_final", "true"});
  EXPECT_NE(prune.exit_code, 0);
  EXPECT_NE(prune.err.find("--prune_audit_refine_final"), std::string::npos) << prune.err;
  const CommandResult run = RunPrunesfm({"run", "--help_all"});
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_NE(run.out.find("--prune_audit_enabled"), std::string::npos);
  EXPECT_NE(run.out.find("--prune_audit_refine_final"), std::string::npos);
}

TEST(Cli, ValuesThatBreakTheLibrarysRulesStopBeforeAnyOutput) {
  // Each flag is in its own range, but the audit would keep an edge below the share at which it
  // re-admits one: the library's Check() refuses the pair, naming the field, before anything runs.
  const fs::path out = ScratchDir("cli_option_rules") / "out";
  for (const char* command : {"run", "prune"}) {
    std::vector<std::string> args = {command, "--database", "/nonexistent/database.db"};
    if (std::string(command) == "run") {
      args.insert(args.end(), {"--output_path", out.string(), "--engine", "GLOBAL_PRUNED"});
    } else {
      args.insert(args.end(), {"--output", (out.string() + ".db")});
    }
    args.insert(args.end(), {"--prune_audit_keep_agreement", "0.9", "--prune_audit_readmit_agreement", "0.8"});
    const CommandResult result = RunPrunesfm(args);
    EXPECT_EQ(result.exit_code, 105) << result.err;
    EXPECT_NE(result.err.find("ModelEdgeAuditOptions::keep_agreement must not exceed readmit_agreement"),
              std::string::npos)
        << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

TEST(Cli, OutOfRangeNumbersSayWhatIsExpectedInOneLine) {
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"run", "--num_threads", "-1"}, "--num_threads: must be zero or more, got -1"},
      {{"run", "--solver_threads", "0"}, "--solver_threads: must be positive, got 0"},
      {{"run", "--positioning_random_starts", "0"}, "--positioning_random_starts"},
      {{"run", "--prune_max_depth", "-1"}, "--prune_max_depth: must be zero or more, got -1"},
      {{"run", "--prune_louvain_resolution", "abc"}, "expected a number, got 'abc'"},
      // NaN and infinity pass a test written as "below min or above max"; these do not.
      {{"run", "--focal", "inf"}, "--focal: expected a finite number, got inf"},
      {{"run", "--ratio", "nan"}, "--ratio: expected a finite number, got nan"},
      {{"run", "--prune_sample_fraction", "nan"}, "expected a finite number, got nan"},
      {{"run", "--seed", "99999999999999999999999"}, "--seed: expected a whole number from 0 to"},
      {{"run", "--seed", "-1"}, "--seed: expected a whole number from 0 to"},
      {{"evaluate", "--inlier_threshold_scene_fraction", "-1"},
       "--inlier_threshold_scene_fraction: must be positive, got -1"},
      // The net under every number (CheckEveryNumber), for options without a check of their own.
      {{"evaluate", "--thresholds", "inf"}, "--thresholds: expected a finite number, got inf"},
      {{"report", "--num_checks", "-1"}, "--num_checks: expected a whole number from 0 to"},
      {{"report", "--num_checks", "18446744073709551616"}, "--num_checks: expected a whole number from 0 to"},
      {{"synth", "--clutter_ratio", "1e400"}, "--clutter_ratio: expected a finite number, got 1e400"}};
  for (const auto& [arguments, message] : cases) {
    std::vector<std::string> argv = arguments;
    for (const char* rest : {"--database", "/nonexistent/database.db", "--image_path", "/nonexistent",
                             "--output_path", "/tmp/prunesfm-never-written"}) {
      argv.push_back(rest);
    }
    const CommandResult result = RunPrunesfm(argv);
    EXPECT_NE(result.exit_code, 0) << arguments[1];
    EXPECT_NE(result.err.find(message), std::string::npos) << result.err;
    EXPECT_LT(result.err.find('\n'), 200u) << result.err;  // no 309-digit bound
    // One line, prefixed as a bad file's error is, saying where the options are listed.
    EXPECT_EQ(CountLines(result.err), 1) << result.err;
    EXPECT_EQ(result.err.rfind("prunesfm: error: ", 0), 0u) << result.err;
    EXPECT_NE(result.err.find("(see 'prunesfm " + arguments[0] + " --help')"), std::string::npos) << result.err;
  }
}

// --quiet, before or after the subcommand: a successful command prints nothing, an error still
// prints its line.
TEST(Cli, QuietPrintsOnlyErrors) {
  const std::string out = ScratchDir("cli_quiet").string();
  for (const std::vector<std::string>& command :
       {std::vector<std::string>{"synth", "--scene", "clean", "--num_views", "6", "-o", out + "/a", "--quiet"},
        std::vector<std::string>{"--quiet", "synth", "--scene", "clean", "--num_views", "6", "-o", out + "/b"}}) {
    const CommandResult result = RunPrunesfm(command);
    EXPECT_EQ(result.exit_code, 0) << result.err;
    EXPECT_EQ(result.err, "");
  }
  const CommandResult verbose = RunPrunesfm({"synth", "--scene", "clean", "--num_views", "6", "-o", out + "/c"});
  EXPECT_NE(verbose.err.find("prunesfm: wrote clean"), std::string::npos) << verbose.err;
  const CommandResult failed = RunPrunesfm({"convert", "-i", "/nonexistent/model.json", "-o", out + "/x.ply", "-q"});
  EXPECT_EQ(failed.exit_code, 1);
  EXPECT_EQ(CountLines(failed.err), 1) << failed.err;
}

// COLMAP's and GLOMAP's spellings (--database_path, --image_path, --output_path) and ours
// (--database, --images, --output, -o) are both accepted wherever the option exists.
TEST(Cli, BothSpellingsOfPathsAreAccepted) {
  const std::vector<std::vector<std::string>> commands = {
      {"reconstruct", "--database_path", "/nonexistent/db.db", "--output_path", "/tmp/prunesfm-never-written"},
      {"prune", "--database_path", "/nonexistent/db.db", "--output_path", "/tmp/prunesfm-never-written.db"},
      {"run", "--database", "/nonexistent/db.db", "--image_path", "/nonexistent", "--output",
       "/tmp/prunesfm-never-written"},
      {"report", "--run", "/nonexistent/run", "--image_path", "/nonexistent", "-o", "/tmp/prunesfm-never.html"},
      {"epipolar", "--model", "/nonexistent/db.json", "--image", "a.jpg", "--image_path", "/nonexistent",
       "--output_path", "/tmp/prunesfm-never.png"}};
  for (const std::vector<std::string>& command : commands) {
    const CommandResult result = RunPrunesfm(command);
    EXPECT_EQ(result.exit_code, 1) << command[0] << ": " << result.err;  // parsed; the file is missing
    EXPECT_NE(result.err.find("/nonexistent"), std::string::npos) << result.err;
  }
}

TEST(Cli, MissingInputFileGivesOneLineNamingTheFile) {
  const CommandResult result = RunPrunesfm({"convert", "--input", "/nonexistent/sfm_data.json", "--output", "/tmp/x.ply"});
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(CountLines(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("/nonexistent/sfm_data.json"), std::string::npos) << result.err;
}

}  // namespace
}  // namespace sfm_pruning::testing
