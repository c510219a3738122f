#include "run_prunesfm.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace sfm_pruning::testing {
namespace {

std::string ShellQuote(const std::string& arg) {
  std::string quoted = "'";
  for (char c : arg) {
    if (c == '\'') {
      quoted += "'\\''";
    } else {
      quoted += c;
    }
  }
  return quoted + "'";
}

std::string Slurp(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

}  // namespace

CommandResult RunPrunesfm(const std::vector<std::string>& args) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("prunesfm_cli_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::string command = ShellQuote(PRUNESFM_EXECUTABLE);
  for (const std::string& arg : args) command += " " + ShellQuote(arg);
  command += " >" + ShellQuote((dir / "out").string()) + " 2>" + ShellQuote((dir / "err").string()) + " </dev/null";
  const int status = std::system(command.c_str());
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.out = Slurp(dir / "out");
  result.err = Slurp(dir / "err");
  std::filesystem::remove_all(dir);
  return result;
}

int CountLines(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  int count = 0;
  while (std::getline(in, line)) {
    if (!line.empty()) ++count;
  }
  return count;
}

}  // namespace sfm_pruning::testing
