// Shared plumbing of the prunesfm subcommands: progress bars, stage timing, exit codes.
#pragma once

#include <chrono>
#include <string>

#include "sfm_pruning/util/progress.hpp"

namespace prunesfm {

// The engines the reconstruction commands accept (listed in --help).
inline constexpr const char* kEngineNames[] = {"GLOBAL", "GLOBAL_PRUNED"};

// A progress callback that draws "\r[#####     ]  42% stage" on stderr when stderr is a terminal
// and prints nothing otherwise (logs and CI stay clean).
sfm_pruning::ProgressCallback TerminalProgressBar();

// Prints an informational line on stderr ("prunesfm: ...").
void Info(const std::string& message);

}  // namespace prunesfm
