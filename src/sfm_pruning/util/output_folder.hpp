// Which folders the tools may write into. A command that writes a folder (a run's outputs, a
// synthetic scene, a COLMAP model, a dense workspace) replaces files in it or the folder as a
// whole, so it must never be pointed at a folder of the user's by mistake. Every folder this
// project writes carries a marker file; a folder may be written when it does not exist, is empty,
// or carries the marker, and any other folder only when the user says so (`--overwrite`).
#pragma once

#include <filesystem>

namespace sfm_pruning {

// The marker file inside every output folder.
inline constexpr char kOutputFolderMarker[] = ".prunesfm_output";

// Throws Error (one line naming `dir`) unless `dir` may receive this project's outputs: an empty
// path and a path that is an existing file are always refused (a file is never replaced by a
// folder); an existing folder must be empty or carry the marker, unless `overwrite`.
void CheckOutputFolder(const std::filesystem::path& dir, bool overwrite);

// Creates `dir` (and its parents) if needed and writes the marker into it.
void ClaimOutputFolder(const std::filesystem::path& dir);

}  // namespace sfm_pruning
