#include "software/cli_support.hpp"

#include <unistd.h>

#include <cstdio>
#include <mutex>

namespace prunesfm {

sfm_pruning::ProgressCallback TerminalProgressBar() {
  if (!::isatty(STDERR_FILENO)) return {};
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

void Info(const std::string& message) { std::fprintf(stderr, "prunesfm: %s\n", message.c_str()); }

}  // namespace prunesfm
