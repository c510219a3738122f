#include "sfm_pruning/util/progress_lines.hpp"

#include <chrono>
#include <cmath>
#include <memory>
#include <mutex>
#include <utility>

namespace sfm_pruning {
namespace {

std::string Seconds(double seconds) {
  return std::to_string(static_cast<long long>(std::lround(seconds))) + " s";
}

struct ProgressLineState {
  std::mutex mutex;
  std::string stage;
  double stage_start = 0.0;
  double last_line = 0.0;
};

}  // namespace

ProgressCallback ProgressLines(std::function<void(const std::string& line)> print, double interval_seconds,
                               SecondsClock clock) {
  if (!clock) {
    clock = []() {
      return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
    };
  }
  auto state = std::make_shared<ProgressLineState>();
  return [state, print = std::move(print), interval_seconds, clock = std::move(clock)](
             const std::string& stage, size_t done, size_t total) {
    std::lock_guard<std::mutex> lock(state->mutex);
    const double now = clock();
    if (stage != state->stage) {
      state->stage = stage;
      state->stage_start = now;
      state->last_line = now;
    }
    const double elapsed = now - state->stage_start;
    const std::string counts = "(" + std::to_string(done) + "/" + std::to_string(total) + ")";
    if (done >= total) {
      if (elapsed >= interval_seconds) print(stage + ": done " + counts + " in " + Seconds(elapsed));
      state->stage.clear();  // the next call starts a stage, even one of the same name
      return;
    }
    if (now - state->last_line < interval_seconds) return;
    state->last_line = now;
    const double fraction = static_cast<double>(done) / static_cast<double>(total);
    std::string line = stage + ": " + std::to_string(static_cast<int>(fraction * 100.0)) + "% " + counts +
                       ", " + Seconds(elapsed) + " elapsed";
    if (done > 0) line += ", about " + Seconds(elapsed * (1.0 - fraction) / fraction) + " left";
    print(line);
  };
}

}  // namespace sfm_pruning
