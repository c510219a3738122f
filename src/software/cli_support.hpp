// Shared plumbing of the prunesfm subcommands: progress bars, stage timing, exit codes.
#pragma once

#include <chrono>
#include <filesystem>
#include <string>

#include <CLI/CLI.hpp>

#include "sfm_pruning/util/progress.hpp"

namespace prunesfm {

// The engines the reconstruction commands accept (listed in --help).
inline constexpr const char* kEngineNames[] = {"GLOBAL", "GLOBAL_PRUNED"};

// A progress callback that draws "\r[#####     ]  42% stage" on stderr when stderr is a terminal
// and prints nothing otherwise (logs and CI stay clean).
sfm_pruning::ProgressCallback TerminalProgressBar();

// Adds `--overwrite`: write into a folder that is neither empty nor an earlier prunesfm output.
CLI::Option* AddOverwriteFlag(CLI::App* cmd, bool* overwrite);

// Refuses `dir` as an output folder unless it is new, empty, an earlier output or `overwrite`
// (util/output_folder.hpp), then creates and marks it. Call before any long work.
void PrepareOutputFolder(const std::filesystem::path& dir, bool overwrite);

// Prints an informational line on stderr ("prunesfm: ...").
void Info(const std::string& message);

}  // namespace prunesfm
