// Shared plumbing of the prunesfm subcommands: progress bars, stage timing, exit codes.
#pragma once

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "sfm_pruning/util/progress.hpp"

namespace prunesfm {

// The engines the reconstruction commands accept (listed in --help).
inline constexpr const char* kEngineNames[] = {"GLOBAL", "GLOBAL_PRUNED"};

// A progress callback on stderr: on a terminal a bar redrawn in place ("\r[#####     ]  42%
// stage"); in a log (stderr redirected) plain lines "prunesfm: stage: 42% (21/50), 12 s elapsed,
// about 16 s left" at most every 10 s of a long stage (util/progress_lines.hpp), nothing for
// stages shorter than that.
sfm_pruning::ProgressCallback ProgressOnStderr();

// What `--overwrite` does to a folder that is neither empty nor an earlier output of the command.
enum class OverwriteMeans {
  kWriteInto,         // run, reconstruct: files of the same names are replaced, others stay
  kReplaceTheFolder,  // synth, convert, export: the folder is replaced with everything in it
};

// Adds `--overwrite` with the help that says which.
CLI::Option* AddOverwriteFlag(CLI::App* cmd, bool* overwrite, OverwriteMeans means);

// For run and reconstruct: refuses `dir` as a run folder unless it is new, empty, an earlier run
// or `overwrite` (util/output_folder.hpp), then creates it and marks it when it is the project's
// (a user's folder written into through `overwrite` stays unmarked). Call before any long work.
void PrepareRunFolder(const std::filesystem::path& dir, bool overwrite);

// Refuses (sfm_pruning::Error naming `output`) an output that is one of `inputs` or a folder
// holding one of them: writing it would replace what is being read. Paths that do not exist yet
// are fine. Call before any work.
void RefuseOutputOverInput(const std::filesystem::path& output, const std::vector<std::filesystem::path>& inputs);

// Ceres logs solver warnings (e.g. a rejected Levenberg-Marquardt step) through glog on stderr,
// and glog warns when used before it is initialised; the commands report through their results
// instead, so every command keeps stderr to its own lines. Called once, first thing in main.
void SilenceSolverLogging();

// Prints an informational line on stderr ("prunesfm: ..."), unless --quiet.
void Info(const std::string& message);

// `--quiet,-q` on `app`, given before or after the subcommand: no informational lines and no
// progress, only errors (which always print).
void AddQuietFlag(CLI::App* app);

}  // namespace prunesfm
