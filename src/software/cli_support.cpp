#include "software/cli_support.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <mutex>

#include <glog/logging.h>

#include "sfm_pruning/util/error.hpp"
#include "sfm_pruning/util/output_folder.hpp"
#include "sfm_pruning/util/progress_lines.hpp"

namespace prunesfm {
namespace {

bool quiet = false;  // set once while the command line is parsed, read after

}  // namespace

sfm_pruning::ProgressCallback ProgressOnStderr() {
  if (quiet) return {};
  if (!::isatty(STDERR_FILENO)) {
    return sfm_pruning::ProgressLines([](const std::string& line) { Info(line); });
  }
  auto mutex = std::make_shared<std::mutex>();
  return [mutex](const std::string& stage, size_t done, size_t total) {
    std::lock_guard<std::mutex> lock(*mutex);
    constexpr int kWidth = 30;
    const double fraction = total == 0 ? 1.0 : static_cast<double>(done) / static_cast<double>(total);
    const int filled = static_cast<int>(fraction * kWidth);
    std::fprintf(stderr, "\r[%-*s] %3d%% %s (%zu/%zu)", kWidth, std::string(filled, '#').c_str(),
                 static_cast<int>(fraction * 100.0), stage.c_str(), done, total);
    if (done >= total) std::fputc('\n', stderr);
    std::fflush(stderr);
  };
}

CLI::Option* AddOverwriteFlag(CLI::App* cmd, bool* overwrite, OverwriteMeans means) {
  return cmd->add_flag("--overwrite", *overwrite,
                       means == OverwriteMeans::kWriteInto
                           ? "Also write into an existing folder that is not empty and not an earlier prunesfm run "
                             "(files of the same names are replaced, the others stay)"
                           : "Also replace an existing folder that is not empty and not an earlier output of this "
                             "kind (everything in it is deleted)");
}

void PrepareRunFolder(const std::filesystem::path& dir, bool overwrite) {
  if (sfm_pruning::CheckOutputFolder(dir, sfm_pruning::OutputFolderKind::kRun, overwrite)) {
    sfm_pruning::ClaimOutputFolder(dir, sfm_pruning::OutputFolderKind::kRun);
  } else {
    std::filesystem::create_directories(dir);
  }
}

void RefuseOutputOverInput(const std::filesystem::path& output, const std::vector<std::filesystem::path>& inputs) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (output.empty() || !fs::exists(output, error)) return;
  const fs::path output_path = fs::weakly_canonical(output, error);
  if (error) return;
  for (const fs::path& input : inputs) {
    if (input.empty() || !fs::exists(input, error)) continue;
    const fs::path input_path = fs::weakly_canonical(input, error);
    if (error) continue;
    if (input_path == output_path) {
      throw sfm_pruning::Error(output.string() + ": the output is the input; write to another path");
    }
    // Is input_path inside output_path?
    const auto [end, unused] = std::mismatch(output_path.begin(), output_path.end(), input_path.begin(),
                                             input_path.end());
    if (end == output_path.end()) {
      throw sfm_pruning::Error(output.string() + ": holds the input " + input.string() +
                               ", which writing the output would replace; write to another path");
    }
  }
}

void SilenceSolverLogging() {
  google::InitGoogleLogging("prunesfm");
  FLAGS_logtostderr = true;
  FLAGS_minloglevel = google::GLOG_FATAL;
}

void Info(const std::string& message) {
  if (!quiet) std::fprintf(stderr, "prunesfm: %s\n", message.c_str());
}

void AddQuietFlag(CLI::App* app) {
  app->add_flag("--quiet,-q", quiet, "Print only errors: no progress, no informational lines");
  app->fallthrough();  // `prunesfm run IMAGES OUT --quiet` as well as `prunesfm --quiet run ...`
}

}  // namespace prunesfm
