// Progress for logs. A progress bar redrawn with '\r' is noise in a log file, and printing nothing
// leaves a batch job silent until it ends; these plain lines say, at most once per interval, where
// a long stage is, how long it has run and about how long it has left. A stage that ends within
// one interval prints nothing, so short runs stay quiet.
#pragma once

#include <functional>
#include <string>

#include "sfm_pruning/util/progress.hpp"

namespace sfm_pruning {

// Seconds on a monotonic clock; the default is std::chrono::steady_clock.
using SecondsClock = std::function<double()>;

// A ProgressCallback that hands `print` lines such as
//   "features: 42% (21/50), 12 s elapsed, about 16 s left"
//   "features: done (50/50) in 31 s"
// The first kind at most every `interval_seconds` once a stage has run that long, the second
// when a stage that ran at least that long finishes. Thread-safe.
ProgressCallback ProgressLines(std::function<void(const std::string& line)> print,
                               double interval_seconds = 10.0, SecondsClock clock = {});

}  // namespace sfm_pruning
