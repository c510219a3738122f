// The README's usage block runs as written, in order, on the generated street: each `prunesfm`
// line (continuations joined, comments dropped) with its relative paths under a scratch folder.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "run_prunesfm.hpp"
#include "support/test_data.hpp"

namespace sfm_pruning::testing {
namespace {
namespace fs = std::filesystem;

// The commands of the ```sh block after the README's "usage block" marker.
std::vector<std::vector<std::string>> UsageCommands(const fs::path& readme) {
  std::ifstream in(readme);
  std::string line;
  while (std::getline(in, line) && line.find("<!-- usage block:") == std::string::npos) {
  }
  std::getline(in, line);  // ```sh
  std::vector<std::vector<std::string>> commands;
  std::string command;
  while (std::getline(in, line) && line.rfind("```", 0) != 0) {
    const size_t comment = line.find(" #");
    if (comment != std::string::npos) line.erase(comment);
    const bool continued = !line.empty() && line.back() == '\\';
    if (continued) line.pop_back();
    command += " " + line;
    if (continued) continue;
    std::istringstream words(command);
    std::vector<std::string> argv;
    for (std::string word; words >> word;) argv.push_back(word);
    if (!argv.empty()) commands.push_back(argv);
    command.clear();
  }
  return commands;
}

TEST(ReadmeUsage, RunsAsWrittenOnTheGeneratedStreet) {
  const fs::path readme = TestDataDir() / ".." / ".." / "README.md";
  const std::vector<std::vector<std::string>> commands = UsageCommands(readme);
  ASSERT_GE(commands.size(), 8u) << "no usage block in " << readme;
  const fs::path scratch = ScratchDir("readme_usage");
  for (const std::vector<std::string>& argv : commands) {
    ASSERT_EQ(argv.front(), "prunesfm");
    std::vector<std::string> args(argv.begin() + 1, argv.end());
    for (std::string& arg : args) {
      if (arg.rfind("out/", 0) == 0) arg = (scratch / arg).string();
    }
    const CommandResult result = RunPrunesfm(args);
    ASSERT_EQ(result.exit_code, 0) << "prunesfm " << ::testing::PrintToString(args) << "\n" << result.err;
  }
  for (const char* output : {"out/street/pruned/sparse/0", "out/street/global/sparse/0", "out/street/report.html",
                             "out/street/pruned.db", "out/street/pruned.json", "out/street/points.ply"}) {
    EXPECT_TRUE(fs::exists(scratch / output)) << output;
  }
}

}  // namespace
}  // namespace sfm_pruning::testing
