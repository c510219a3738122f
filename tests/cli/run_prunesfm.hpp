// Runs the prunesfm executable as a user would, capturing exit code and output.
#pragma once

#include <string>
#include <vector>

namespace sfm_pruning::testing {

struct CommandResult {
  int exit_code = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};

// Runs `prunesfm <args...>` (arguments are shell-quoted) and waits for it.
CommandResult RunPrunesfm(const std::vector<std::string>& args);

// Number of non-empty lines in `text`.
int CountLines(const std::string& text);

}  // namespace sfm_pruning::testing
